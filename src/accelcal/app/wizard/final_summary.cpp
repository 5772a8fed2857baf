#include "accelcal/app/wizard/final_summary.h"

#include <cmath>

#include <fmt/core.h>

#include "accelcal/base/sensor_model.h"

namespace accelcal {
namespace {

std::string ValueSigma(const ReportParameter& p, double factor, int digits) {
  const std::string value = fmt::format("{:.{}f}", p.value * factor, digits);
  if (p.held || !std::isfinite(p.sigma)) return value + " (held)";
  return fmt::format("{} +- {:.{}f}", value, p.sigma * factor, digits);
}

// One kind of parameter over its three axes, in columns:
//   "bias (counts)        x 2051.31 +- 0.12  y 2039.60 +- 0.12  z 2062.80 +- 0.12"
std::string Triple(const ReportModel& r, const char* label, int first, const char* names[3],
                   double factor, int digits) {
  std::string line = fmt::format("{:<21}", label);
  for (int i = 0; i < 3; ++i) {
    const std::string cell =
        fmt::format("{} {}", names[i], ValueSigma(r.parameters[static_cast<size_t>(first + i)], factor, digits));
    line += i == 2 ? cell : fmt::format("{:<19}", cell + " ");
  }
  return line;
}

std::string LimitFailed(const LimitCheck& c) {
  const std::string unit = c.unit.empty() ? "" : " " + c.unit;
  return fmt::format("  limit failed: {} {:.4g}{}, {} {:.4g}", c.what, c.value, unit,
                     c.at_least ? "at least" : "at most", c.limit);
}

}  // namespace

FinalSummary BuildFinalSummary(const ReportModel& r, const std::vector<std::string>& report_paths) {
  FinalSummary s;
  s.verdict = r.verdict;
  s.lines.push_back(fmt::format("Verdict: {}", VerdictToString(r.verdict)));
  for (const LimitCheck& c : r.checks)
    if (!c.pass) s.lines.push_back(LimitFailed(c));
  for (const std::string& why : r.incomplete) s.lines.push_back("  incomplete: " + why);
  if (r.parameters.size() >= static_cast<size_t>(kNumBaseParameters)) {
    static const char* axes[3] = {"x", "y", "z"};
    static const char* angles[3] = {"yz", "zy", "zx"};
    s.lines.push_back(Triple(r, "bias (counts)", kBiasX, axes, 1.0, 2));
    s.lines.push_back(Triple(r, "scale (counts/m/s^2)", kScaleX, axes, 1.0, 4));
    s.lines.push_back(Triple(r, "misalignment (mrad)", kMisYZ, angles, 1e3, 3));
  }
  s.lines.push_back(fmt::format("{:<21}{:.3g} m/s^2 over {} captures (noise alone: {:.3g})",
                                "residual RMS", r.residual_rms_mps2, r.captures_used, r.noise_rms_mps2));
  for (const std::string& path : report_paths) s.lines.push_back("Report: " + path);
  return s;
}

}  // namespace accelcal
