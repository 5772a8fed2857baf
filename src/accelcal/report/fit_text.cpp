#include "accelcal/report/fit_text.h"

#include <cmath>

#include <fmt/core.h>

#include "accelcal/sensor_model.h"

namespace accelcal {
namespace {

std::string Conditions(const CaptureRecord& c) {
  if (c.kind == CaptureKind::kTurntable) return fmt::format("r={:.3f} m {:.1f} rpm", c.radius_m, c.rpm);
  if (std::isfinite(c.t_start_s)) return fmt::format("t={:.1f}-{:.1f} s", c.t_start_s, c.t_end_s);
  return "";
}

std::string Row(const CaptureRecord& c) {
  std::string status;
  if (!c.used) {
    status = "left out: " + c.reason;
  } else if (std::isfinite(c.residual_mps2)) {
    status = fmt::format("{:+.5f} m/s^2 ({:+.1f} sigma)", c.residual_mps2,
                         c.sigma_mps2 > 0 ? c.residual_mps2 / c.sigma_mps2 : 0.0);
  }
  std::string label = c.label.size() > 14 ? c.label.substr(0, 13) + "~" : c.label;
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

std::string FormatCaptureTable(const std::vector<CaptureRecord>& captures) {
  std::string out = fmt::format("{:>4} {:<9} {:<14} {:>6} {:<22} {}\n", "id", "kind", "label",
                                "n", "conditions", "residual |a|-|f|");
  for (const CaptureRecord& c : captures) out += Row(c);
  return out;
}

std::string FormatCaptureTable(const std::vector<Capture>& captures, const FitSummary& summary) {
  return FormatCaptureTable(MakeCaptureRecords(captures, summary));
}

std::string FormatFitReport(const Calibration& cal, const FitSummary& summary) {
  std::string out = "\n" + summary.BriefReport() + "\n\nparameters (1-sigma):\n";
  for (int i = 0; i < kNumBaseParameters; ++i) {
    out += fmt::format("  {:<8} {:>14.6f} +- {:<11.6f} {}\n", ParameterName(i), summary.parameters(i),
                       summary.uncertainty(i), ParameterUnit(i));
  }
  out += fmt::format("\nresiduals: RMS {:.5f} m/s^2, max |r| {:.5f} m/s^2, chi2 {:.2f} on {} dof\n",
                     summary.residual_rms_mps2, summary.residual_max_abs_mps2, summary.chi2, summary.dof);
  if (summary.uncertainty_scale > 1.0)
    out += fmt::format("uncertainties scaled by sqrt(chi2/dof) = {:.2f}: the residuals exceed what "
                       "the captures' noise explains\n", summary.uncertainty_scale);
  out += fmt::format("condition number {:.3g}", summary.condition_number);
  if (summary.most_correlated.first >= 0)
    out += fmt::format("; most correlated: {} and {} (rho {:+.3f})",
                       summary.parameter_labels[summary.most_correlated.first],
                       summary.parameter_labels[summary.most_correlated.second],
                       summary.most_correlated.rho);
  out += "\n";
  for (const std::string& w : summary.warnings) out += "warning: " + w + "\n";
  out += "\ncaptures:\n" + FormatCaptureTable(cal.captures);
  return out;
}

}  // namespace accelcal
