#include "accelcal/report/calibration_text.h"

#include <fmt/format.h>

#include "accelcal/report/fit_text.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal {

std::string FormatCalibrationText(const Calibration& cal) {
  std::string out = fmt::format("gravity: {}\n\nparameters (1-sigma):\n", cal.gravity.Describe());
  const Eigen::Matrix<double, kNumBaseParameters, 1> value = cal.model.ToVector();
  const Eigen::Matrix<double, kNumBaseParameters, 1> sigma = cal.uncertainty.ToVector();
  for (int i = 0; i < kNumBaseParameters; ++i)
    out += fmt::format("  {:<8} {:>14.6f} +- {:<11.6f} {}\n", ParameterName(i), value(i), sigma(i),
                       ParameterUnit(i));
  out += fmt::format("\nresiduals: RMS {:.5f} m/s^2, max |r| {:.5f} m/s^2\n", cal.residual_rms_mps2,
                     cal.residual_max_abs_mps2);
  const std::vector<std::string> names = cal.EffectNames();
  out += fmt::format("effects added: {}\n", names.empty() ? std::string("none") : fmt::format("{}", fmt::join(names, ", ")));
  out += "\ncaptures:\n" + FormatCaptureTable(cal.captures);
  return out;
}

}  // namespace accelcal
