#include "accelcal/report/fit_text.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>
#include <fmt/format.h>

#include "accelcal/base/safe_text.h"
#include "accelcal/report/limit_checks.h"
#include "accelcal/report/uncertainty_text.h"

namespace accelcal {
namespace {

std::string Conditions(const CalibrationCapture& c) {
  if (c.kind == CaptureKind::kTurntable) return fmt::format("r={:.3f} m {:.1f} rpm", c.radius_m, c.rpm);
  if (std::isfinite(c.t_start_s)) return fmt::format("t={:.1f}-{:.1f} s", c.t_start_s, c.t_end_s);
  return "";
}

std::string Row(const CalibrationCapture& c) {
  std::string status;
  if (!c.used) {
    status = "left out: " + c.reason;
  } else if (std::isfinite(c.residual_mps2)) {
    status = fmt::format("{:+.5f} m/s^2 ({:+.1f} sigma)", c.residual_mps2,
                         c.sigma_mps2 > 0 ? c.residual_mps2 / c.sigma_mps2 : 0.0);
  }
  const std::string label = ShortDisplayText(c.label, 14);  // a label may hold anything
  return fmt::format("{:>4} {:<9} {:<14} {:>6} {:<22} {}\n", c.id, CaptureKindToString(c.kind),
                     label, c.n_samples, Conditions(c), status);
}

}  // namespace

std::string FormatIntervals(const StaticDetection& detection, const StaticDetectorOptions& options) {
  std::string out = fmt::format(
      "static intervals: {} found (window {} samples; still-start variance norm {:.3f} counts^2 "
      "over the first {:g} s; threshold {:g} x = {:.3f} counts^2)\n",
      detection.intervals.size(), options.window_samples, detection.quiet_variance_norm_counts2,
      options.init_static_s, options.threshold_multiplier, detection.threshold_counts2);
  for (size_t i = 0; i < detection.intervals.size(); ++i) {
    const StaticInterval& iv = detection.intervals[i];
    out += fmt::format("  {:>3}  {:9.3f} - {:9.3f} s  {:>6} samples\n", i + 1, iv.t_start_s,
                       iv.t_end_s, iv.num_samples());
  }
  return out;
}

std::string FormatCaptureTable(const std::vector<CalibrationCapture>& captures) {
  std::string out = fmt::format("{:>4} {:<9} {:<14} {:>6} {:<22} {}\n", "id", "kind", "label",
                                "n", "conditions", "residual |a|-|f|");
  for (const CalibrationCapture& c : captures) out += Row(c);
  return out;
}

std::string FormatCaptureTable(const std::vector<Capture>& captures, const FitSummary& summary) {
  return FormatCaptureTable(MakeCalibrationCaptures(captures, summary));
}

std::string FormatFitReport(const Calibration& cal, const FitSummary& summary) {
  // Warnings the calibration adds to the fit's own (a capture in another pose than asked).
  std::string extra;
  for (const std::string& w : cal.fit.warnings)
    if (std::find(summary.warnings.begin(), summary.warnings.end(), w) == summary.warnings.end())
      extra += "warning: " + w + "\n";
  for (const UncertaintyLimit& l : cal.limited_by) extra += "the calibration is " + l.words + "\n";
  return "\n" + summary.FullReport() + extra + "\ncaptures:\n" + FormatCaptureTable(cal.captures);
}

std::string FormatExpandedResults(const Calibration& cal) {
  std::string out;
  if (!cal.budget)
    out = "results +- U = 2 x the fit's 1-sigma (k = 2; type A alone: no uncertainty budget):\n";
  else if (cal.budget->not_stated.empty())
    out = "results +- U (k = 2, about 95 %), as the certificate states them:\n";
  else
    out = fmt::format("results +- U (k = 2, about 95 %) of the fit and the gravity's uncertainty; not\n"
                      "in U, not stated here: {} (a wizard session's budget holds them):\n",
                      fmt::join(cal.budget->not_stated, ", "));
  const auto value = cal.model.ToVector();
  for (int i = 0; i < kNumBaseParameters; ++i) {
    const double u = CertificateExpandedUncertainty(cal, i);
    const RoundedResult r = RoundToUncertainty(value(i), u);
    out += fmt::format("  {:<8} {:>14} {:<10} {}\n", ParameterName(i), r.value,
                       std::isnan(u) ? "(held)" : "+- " + r.uncertainty, ParameterUnit(i));
  }
  return out;
}

}  // namespace accelcal
