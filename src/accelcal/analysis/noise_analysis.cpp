#include "accelcal/analysis/noise_analysis.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include <fmt/core.h>

#include "accelcal/calibration/apply.h"
#include "accelcal/base/error.h"

namespace accelcal::analysis {
namespace {

// Minimum number of PSD bins kept below the flat band: the lowest bins carry the window's
// leakage of drift and flicker.
constexpr int kExcludedLowBins = 4;

double Mean(const std::vector<double>& x) {
  double sum = 0.0;
  for (double v : x) sum += v;
  return sum / static_cast<double>(x.size());
}

double SampleStd(const std::vector<double>& x) {
  const double mean = Mean(x);
  double ss = 0.0;
  for (double v : x) ss += (v - mean) * (v - mean);
  return std::sqrt(ss / static_cast<double>(x.size() - 1));
}

double MedianInterval(const std::vector<Sample>& samples, const std::string& label) {
  std::vector<double> dt;
  dt.reserve(samples.size());
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const double d = samples[i].t_s - samples[i - 1].t_s;
    if (!(d > 0.0))
      throw Error(fmt::format("record {}: t does not increase at sample {} (t = {})", label, i,
                              samples[i].t_s));
    dt.push_back(d);
  }
  std::nth_element(dt.begin(), dt.begin() + static_cast<long>(dt.size() / 2), dt.end());
  return dt[dt.size() / 2];
}

// Per-axis series in the report's unit, and in raw counts.
struct AxisSeries {
  std::array<std::vector<double>, 3> value;
  std::array<std::vector<double>, 3> counts;
};

AxisSeries SplitAxes(const NoiseRecord& record, const CalibrationApplier* applier) {
  AxisSeries s;
  for (const Sample& sample : record.samples) {
    const Eigen::Vector3d v = applier ? applier->Apply(sample) : sample.raw_counts;
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(sample.raw_counts(i)))
        throw Error(fmt::format("record {}: a reading at t = {} is not finite", record.label,
                                sample.t_s));
      s.value[static_cast<std::size_t>(i)].push_back(v(i));
      s.counts[static_cast<std::size_t>(i)].push_back(sample.raw_counts(i));
    }
  }
  return s;
}

// Bins 1 .. L/2 averaged over at most max_points log-spaced bands; a band without a bin is
// skipped, so the low end keeps single bins.
SpectrumPoints ReduceSpectrum(const std::array<PowerSpectrum, 3>& psd, int max_points) {
  SpectrumPoints out;
  const std::vector<double>& f = psd[0].frequency_hz;
  const std::size_t last = f.size() - 1;
  const double f_lo = f[1];
  const double f_hi = f[last];
  const double log_step = std::log(f_hi / f_lo) / max_points;
  std::size_t k = 1;
  for (int band = 0; band < max_points && k <= last; ++band) {
    const double edge = band + 1 == max_points ? f_hi * 1.0001 : f_lo * std::exp(log_step * (band + 1));
    double sum_f = 0.0;
    std::array<double, 3> sum_p{0.0, 0.0, 0.0};
    int count = 0;
    for (; k <= last && f[k] < edge; ++k) {
      sum_f += f[k];
      for (std::size_t a = 0; a < 3; ++a) sum_p[a] += psd[a].density[k];
      ++count;
    }
    if (count == 0) continue;
    out.frequency_hz.push_back(sum_f / count);
    for (std::size_t a = 0; a < 3; ++a) out.density[a].push_back(sum_p[a] / count);
  }
  return out;
}

RecordNoise AnalyzeRecord(const NoiseRecord& record, const NoiseAnalysisOptions& options,
                          const CalibrationApplier* applier) {
  if (record.samples.size() < 16)
    throw Error(fmt::format("record {}: {} samples are too few for a noise analysis (at least 16)",
                            record.label, record.samples.size()));
  RecordNoise r;
  r.label = record.label;
  r.date = record.date;
  r.num_samples = static_cast<long>(record.samples.size());
  r.rate_hz = 1.0 / MedianInterval(record.samples, record.label);
  r.duration_s = record.samples.back().t_s - record.samples.front().t_s;
  const AxisSeries series = SplitAxes(record, applier);

  std::array<PowerSpectrum, 3> psd;
  for (std::size_t a = 0; a < 3; ++a) psd[a] = WelchPsd(series.value[a], r.rate_hz, options.welch);
  r.segment_length = psd[0].segment_length;
  r.num_segments = psd[0].num_segments;
  r.resolution_hz = psd[0].resolution_hz;
  const double nyquist_hz = 0.5 * r.rate_hz;
  r.band_low_hz = std::max(options.band_low_fraction * nyquist_hz, kExcludedLowBins * r.resolution_hz);
  r.band_high_hz = options.band_high_fraction * nyquist_hz;
  std::array<double, 3> band_sum{0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < psd[0].frequency_hz.size(); ++k) {
    const double f = psd[0].frequency_hz[k];
    if (f < r.band_low_hz || f > r.band_high_hz) continue;
    for (std::size_t a = 0; a < 3; ++a) band_sum[a] += psd[a].density[k];
    ++r.band_bins;
  }
  if (r.band_bins == 0)
    throw Error(fmt::format("record {}: no PSD bin in the flat band {:.3g}..{:.3g} Hz (record too "
                            "short: {} samples)", record.label, r.band_low_hz, r.band_high_hz,
                            r.num_samples));
  for (std::size_t a = 0; a < 3; ++a) {
    AxisNoise& axis = r.axes[a];
    axis.mean = Mean(series.value[a]);
    axis.std = SampleStd(series.value[a]);
    axis.std_counts = SampleStd(series.counts[a]);
    // N, the convention of IEEE 952 and Kalibr (and of the Allan read-offs): one-sided PSD
    // = 2 N^2 for white noise.
    axis.density = std::sqrt(band_sum[a] / r.band_bins / 2.0);
    axis.normality = JarqueBera(series.value[a], axis.std_counts, options.normality_alpha,
                                options.quantization_limit_counts);
  }
  r.spectrum = ReduceSpectrum(psd, options.max_spectrum_points);
  return r;
}

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

NoiseReport AnalyzeNoise(const std::vector<NoiseRecord>& records,
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
  for (const NoiseRecord& record : records)
    report.records.push_back(AnalyzeRecord(record, options, applier.get()));
  report.repeatability = Repeatability(report.records, options.min_days, &report.warnings);
  return report;
}

}  // namespace accelcal::analysis
