#include "accelcal/analysis/noise_analysis.h"

#include <map>
#include <memory>

#include <fmt/core.h>

#include "accelcal/analysis/record_noise.h"
#include "accelcal/calibration/apply.h"
#include "accelcal/base/error.h"

namespace accelcal::analysis {
namespace {

BiasRepeatability Repeatability(const std::vector<RecordNoise>& records, int min_days,
                                std::vector<std::string>* warnings) {
  BiasRepeatability rep;
  std::map<std::string, std::string> first_of_day;  // date -> label counted
  int undated = 0;
  for (const RecordNoise& r : records) {
    if (r.date.empty()) {
      ++undated;
    } else if (auto it = first_of_day.find(r.date); it != first_of_day.end()) {
      warnings->push_back(fmt::format(
          "record {} is from {}, a day already counted ({}): left out of the day-to-day figure",
          r.label, r.date, it->second));
      continue;
    } else {
      first_of_day[r.date] = r.label;
    }
    rep.labels.push_back(r.label);
    rep.dates.push_back(r.date);
    rep.means.emplace_back(r.axes[0].mean, r.axes[1].mean, r.axes[2].mean);
  }
  if (undated > 0)
    warnings->push_back(fmt::format("{} record(s) carry no date: each is taken as a day of its own",
                                    undated));
  rep.num_days = static_cast<int>(rep.means.size());
  if (rep.num_days < min_days)
    warnings->push_back(fmt::format(
        "turn-on bias repeatability needs records on {} different days; have {}", min_days,
        rep.num_days));
  if (rep.num_days < 2) return rep;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Vector3d lo = rep.means[0], hi = rep.means[0];
  for (const Eigen::Vector3d& m : rep.means) {
    mean += m;
    lo = lo.cwiseMin(m);
    hi = hi.cwiseMax(m);
  }
  mean /= rep.num_days;
  Eigen::Vector3d ss = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& m : rep.means) ss += (m - mean).cwiseAbs2();
  rep.std_of_means = (ss / (rep.num_days - 1)).cwiseSqrt();
  rep.max_minus_min = hi - lo;
  return rep;
}

}  // namespace

std::string NoiseAnalysisOptions::Validate() const {
  if (!(band_low_fraction >= 0.0 && band_low_fraction < band_high_fraction &&
        band_high_fraction <= 1.0))
    return "the flat band needs 0 <= band_low_fraction < band_high_fraction <= 1";
  if (max_spectrum_points < 2) return "max_spectrum_points must be at least 2";
  if (!(normality_alpha > 0.0 && normality_alpha < 1.0)) return "normality_alpha must be in (0, 1)";
  if (!(quantization_limit_counts >= 0.0)) return "quantization_limit_counts must not be negative";
  if (min_days < 2) return "min_days must be at least 2";
  return welch.Validate();
}

NoiseRecordSource ReplayOf(const NoiseRecord& record) {
  const std::vector<Sample>* samples = &record.samples;
  return {record.label, record.date, [samples](const SamplePieceSink& sink) {
            sink(samples->data(), samples->size());
          }};
}

NoiseRecordSource HeldRecord(std::string label, std::string date, std::vector<Sample> samples) {
  auto held = std::make_shared<const std::vector<Sample>>(std::move(samples));
  return {std::move(label), std::move(date), [held](const SamplePieceSink& sink) {
            sink(held->data(), held->size());
          }};
}

NoiseReport AnalyzeNoise(const std::vector<NoiseRecord>& records,
                         const NoiseAnalysisOptions& options, const Calibration* calibration) {
  std::vector<NoiseRecordSource> sources;
  for (const NoiseRecord& record : records) sources.push_back(ReplayOf(record));
  return AnalyzeNoiseSources(sources, options, calibration);
}

NoiseReport AnalyzeNoiseSources(const std::vector<NoiseRecordSource>& records,
                                const NoiseAnalysisOptions& options, const Calibration* calibration) {
  if (std::string why = options.Validate(); !why.empty()) throw Error("noise analysis: " + why);
  if (records.empty()) throw Error("noise analysis: no records");
  NoiseReport report;
  std::unique_ptr<CalibrationApplier> applier;
  if (calibration != nullptr) {
    applier = std::make_unique<CalibrationApplier>(*calibration);
    report.unit = "m/s^2";
    report.calibration_source = calibration->source;
  }
  for (const NoiseRecordSource& record : records)
    report.records.push_back(AnalyzeRecordNoise(record, options, applier.get()));
  report.repeatability = Repeatability(report.records, options.min_days, &report.warnings);
  return report;
}

}  // namespace accelcal::analysis
