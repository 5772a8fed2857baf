#include "accelcal/io/noise_file.h"

#include <cmath>

#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/detail/json_values.h"
#include "accelcal/io/detail/read_file.h"

namespace accelcal {
namespace {

using namespace detail;  // the JSON helpers
using analysis::AxisNoise;
using analysis::NoiseReport;
using analysis::NormalityTest;
using analysis::RecordNoise;

constexpr const char* kNoiseAxisNames[3] = {"x", "y", "z"};

nlohmann::json NormalityJson(const NormalityTest& t) {
  return {{"test", "jarque-bera"},
          {"statistic", JsonNumber(t.statistic)},
          {"p_value", JsonNumber(t.p_value)},
          {"skewness", JsonNumber(t.skewness)},
          {"excess_kurtosis", JsonNumber(t.excess_kurtosis)},
          {"verdict", std::string(analysis::NormalityVerdictToString(t.verdict))},
          {"note", t.note}};
}

nlohmann::json RecordJson(const RecordNoise& r) {
  nlohmann::json axes = nlohmann::json::object();
  nlohmann::json spectrum = {{"frequency_hz", JsonNumbers(r.spectrum.frequency_hz)}};
  for (std::size_t a = 0; a < 3; ++a) {
    const AxisNoise& axis = r.axes[a];
    axes[kNoiseAxisNames[a]] = {{"mean", JsonNumber(axis.mean)},
                           {"std", JsonNumber(axis.std)},
                           {"std_counts", JsonNumber(axis.std_counts)},
                           {"density", JsonNumber(axis.density)},
                           {"normality", NormalityJson(axis.normality)}};
    spectrum[kNoiseAxisNames[a]] = JsonNumbers(r.spectrum.density[a]);
  }
  return {{"label", r.label},
          {"date", r.date.empty() ? nlohmann::json() : nlohmann::json(r.date)},
          {"n_samples", r.num_samples},
          {"rate_hz", JsonNumber(r.rate_hz)},
          {"duration_s", JsonNumber(r.duration_s)},
          {"welch", {{"segment_length", r.segment_length},
                     {"segments", r.num_segments},
                     {"resolution_hz", JsonNumber(r.resolution_hz)}}},
          {"flat_band_hz", {JsonNumber(r.band_low_hz), JsonNumber(r.band_high_hz)}},
          {"flat_band_bins", r.band_bins},
          {"axes", axes},
          {"spectrum", spectrum}};
}

}  // namespace

nlohmann::json NoiseReportToJson(const NoiseReport& report) {
  nlohmann::json records = nlohmann::json::array();
  for (const RecordNoise& r : report.records) records.push_back(RecordJson(r));
  const analysis::BiasRepeatability& rep = report.repeatability;
  nlohmann::json used = nlohmann::json::array();
  for (std::size_t i = 0; i < rep.labels.size(); ++i) {
    used.push_back({{"label", rep.labels[i]},
                    {"date", rep.dates[i].empty() ? nlohmann::json() : nlohmann::json(rep.dates[i])},
                    {"mean", JsonTriadOrNull(rep.means[i])}});
  }
  return {{"format", "accelcal-noise/1"},
          {"unit", report.unit},
          {"density_unit", report.unit + "/sqrt(Hz)"},
          {"psd_unit", report.unit + "^2/Hz"},
          {"calibration", report.calibration_source.empty()
                              ? nlohmann::json()
                              : nlohmann::json(report.calibration_source)},
          {"records", records},
          {"repeatability", {{"days", rep.num_days},
                             {"records", used},
                             {"std_of_means", JsonTriadOrNull(rep.std_of_means)},
                             {"max_minus_min", JsonTriadOrNull(rep.max_minus_min)}}},
          {"warnings", report.warnings}};
}

std::string NoiseFileText(const NoiseReport& report) { return detail::JsonText(NoiseReportToJson(report)) + "\n"; }

NoiseSection ParseNoiseText(const std::string& text, const std::string& source) {
  return ParseNoiseJson(ParseJsonText(text, source), source);
}

NoiseSection ReadNoiseFile(const std::string& path) { return ParseNoiseText(ReadWholeFile(path), path); }

}  // namespace accelcal
