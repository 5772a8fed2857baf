#include "accelcal/report/noise_text.h"

#include <cmath>

#include <fmt/core.h>

namespace accelcal {
namespace {

using analysis::AxisNoise;
using analysis::NoiseReport;
using analysis::NormalityTest;
using analysis::NormalityVerdict;
using analysis::RecordNoise;

constexpr const char* kAxisNames[3] = {"x", "y", "z"};

// "normal (p 0.43)", "NOT NORMAL (p 3e-12)", "quantized: not tested".
std::string VerdictText(const NormalityTest& t) {
  switch (t.verdict) {
    case NormalityVerdict::kNormal: return fmt::format("normal (JB p {:.2g})", t.p_value);
    case NormalityVerdict::kNotNormal: return fmt::format("NOT normal (JB p {:.2g})", t.p_value);
    case NormalityVerdict::kQuantized: return "not tested: < 1 count";
  }
  return "";
}

void AppendRecordText(const RecordNoise& r, std::string* out) {
  *out += fmt::format("\nRecord {}{}: {} samples at {:.4g} Hz, {:.1f} s\n", r.label,
                      r.date.empty() ? "" : " (" + r.date + ")", r.num_samples, r.rate_hz,
                      r.duration_s);
  *out += fmt::format("  Welch PSD: {} segments of {} samples ({:.3g} Hz); flat band "
                      "{:.3g}-{:.3g} Hz\n",
                      r.num_segments, r.segment_length, r.resolution_hz, r.band_low_hz,
                      r.band_high_hz);
  *out += fmt::format("  {:<4} {:>13} {:>12} {:>12}  {}\n", "axis", "mean", "std", "density",
                      "normality");
  for (std::size_t a = 0; a < 3; ++a) {
    const AxisNoise& axis = r.axes[a];
    *out += fmt::format("  {:<4} {:>13.7g} {:>12.5g} {:>12.5g}  {}\n", kAxisNames[a], axis.mean,
                        axis.std, axis.density, VerdictText(axis.normality));
  }
  for (std::size_t a = 0; a < 3; ++a) {
    if (r.axes[a].normality.verdict == NormalityVerdict::kNotNormal)
      *out += fmt::format("  {}: {}\n", kAxisNames[a], r.axes[a].normality.note);
  }
  bool quantized_said = false;
  for (std::size_t a = 0; a < 3 && !quantized_said; ++a) {
    if (r.axes[a].normality.verdict != NormalityVerdict::kQuantized) continue;
    *out += "  (std below 1 count: the ADC's rounding dominates; normality not testable)\n";
    quantized_said = true;
  }
}

// `text` as "  - " + lines of at most 80 columns, continued with 4 spaces, broken at blanks.
std::string Bullet(const std::string& text) {
  constexpr std::size_t kWidth = 80;
  std::string out, line = "  -";
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find(' ', at);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(at, end - at);
    if (line.size() + 1 + word.size() > kWidth && line.size() > 4) {
      out += line + "\n";
      line = "   ";
    }
    line += " " + word;
    at = end + 1;
  }
  return out + line + "\n";
}

}  // namespace

std::string FormatNoiseText(const NoiseReport& report) {
  std::string out = fmt::format(
      "Noise analysis: {} record(s); unit {} (density {}/sqrt(Hz)){}\n", report.records.size(),
      report.unit, report.unit,
      report.calibration_source.empty() ? "" : "\nCalibration: " + report.calibration_source);
  for (const RecordNoise& r : report.records) AppendRecordText(r, &out);
  const analysis::BiasRepeatability& rep = report.repeatability;
  out += fmt::format("\nTurn-on bias repeatability (day-to-day change of the mean), {} day(s)\n",
                     rep.num_days);
  for (std::size_t i = 0; i < rep.labels.size(); ++i) {
    out += fmt::format("  {:<10}  {:<24} mean {:.7g} {:.7g} {:.7g}\n",
                       rep.dates[i].empty() ? "no date" : rep.dates[i], rep.labels[i],
                       rep.means[i](0), rep.means[i](1), rep.means[i](2));
  }
  if (rep.num_days >= 2) {
    out += fmt::format("  {:<4} {:>14} {:>14}\n", "axis", "std of means", "max - min");
    for (int a = 0; a < 3; ++a) {
      out += fmt::format("  {:<4} {:>14.5g} {:>14.5g}\n", kAxisNames[a], rep.std_of_means(a),
                         rep.max_minus_min(a));
    }
  } else {
    out += "  not computed: needs records on at least 2 days\n";
  }
  if (!report.warnings.empty()) {
    out += "\nWarnings:\n";
    for (const std::string& w : report.warnings) out += Bullet(w);
  }
  out += "\n(Spectra: --format json.)\n";
  return out;
}

}  // namespace accelcal
