#include "accelcal/app/wizard/fit_words.h"

#include <cmath>
#include <sstream>

#include <fmt/core.h>

#include "accelcal/base/safe_text.h"

namespace accelcal {
namespace {

constexpr size_t kFitLineWidth = 78;

void AddWrapped(const std::string& text, std::vector<std::string>* out) {
  std::string line;
  std::istringstream words(text);
  for (std::string w; words >> w;) {
    if (!line.empty() && line.size() + 1 + w.size() > kFitLineWidth) {
      out->push_back(line);
      line = "  ";
    }
    line += (line.empty() || line == "  " ? "" : " ") + w;
  }
  if (!line.empty()) out->push_back(line);
}

// How the captures' misfit compares with what their own noise explains.
std::string Agreement(double ratio) {
  if (!std::isfinite(ratio)) return "";
  if (ratio <= 2.0) return "as well as the sensor's noise allows";
  if (ratio <= 5.0) return "somewhat worse than the sensor's noise: a capture or the bench may be a little off";
  return "much worse than the sensor's noise: a capture or the bench is off; look at the captures (d) "
         "before going on";
}

// "+y radial, +z up at 100 mm, 120 rpm": a turntable run by what tells it from its like.
std::string Named(const CalibrationCapture& c) {
  const std::string label = ShortDisplayText(c.label, 40);
  if (c.kind != CaptureKind::kTurntable || !std::isfinite(c.radius_m) || !std::isfinite(c.rpm)) return label;
  return fmt::format("{} at {:g} mm, {:g} rpm", label, c.radius_m * 1000.0, c.rpm);
}

}  // namespace

std::vector<std::string> FitInPlainWords(const Calibration& cal) {
  std::vector<std::string> out;
  int used = 0;
  double noise2 = 0.0;
  const CalibrationCapture* worst = nullptr;
  double worst_ratio = 0.0;
  for (const CalibrationCapture& c : cal.captures) {
    if (!c.used) continue;
    ++used;
    if (std::isfinite(c.sigma_mps2)) noise2 += c.sigma_mps2 * c.sigma_mps2;
    const double ratio = c.sigma_mps2 > 0.0 ? std::fabs(c.residual_mps2) / c.sigma_mps2 : 0.0;
    if (std::isfinite(ratio) && ratio > worst_ratio) {
      worst_ratio = ratio;
      worst = &c;
    }
  }
  const double noise_rms = used > 0 ? std::sqrt(noise2 / used) : NAN;
  const double ratio = noise_rms > 0.0 ? cal.residual_rms_mps2 / noise_rms : NAN;
  std::string agreement = fmt::format("{} captures fitted: they agree with one calibration to {:.2g} m/s^2 on "
                                      "average",
                                      used, cal.residual_rms_mps2);
  if (std::isfinite(ratio)) agreement += fmt::format(", {:.1f} x what the sensor's noise explains: {}", ratio, Agreement(ratio));
  AddWrapped(agreement + ".", &out);
  // A capture that stands out from the others' agreement (4 x its noise and more).
  if (worst != nullptr && worst_ratio > 4.0 && std::isfinite(ratio) && worst_ratio > 2.0 * ratio)
    AddWrapped(fmt::format("Fits worst: capture {} ({}), {:.2g} m/s^2 off, {:.0f} x its noise.", worst->id,
                           Named(*worst), std::fabs(worst->residual_mps2), worst_ratio),
               &out);
  for (const CalibrationCapture& c : cal.captures)
    if (!c.used)
      AddWrapped(fmt::format("Left out: capture {} ({}): {}", c.id, Named(c), c.reason), &out);
  if (!cal.fit.warnings.empty())
    AddWrapped(fmt::format("The fit has {} note{} worth a look: d shows {}.", cal.fit.warnings.size(),
                           cal.fit.warnings.size() == 1 ? "" : "s", cal.fit.warnings.size() == 1 ? "it" : "them"),
               &out);
  AddWrapped("d shows the parameters with their 1-sigma, the fit's statistics and every capture.", &out);
  return out;
}

}  // namespace accelcal
