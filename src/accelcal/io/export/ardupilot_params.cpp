#include "accelcal/io/export/ardupilot_params.h"

#include <cmath>

#include <fmt/format.h>

namespace accelcal {
namespace {

constexpr const char* kAxes[3] = {"X", "Y", "Z"};
constexpr double kOffsetRangeMps2 = 3.5;            // INS_ACCOFFS_* @Range -3.5 3.5
constexpr double kScaleMin = 0.8, kScaleMax = 1.2;  // INS_ACCSCAL_* @Range 0.8 1.2

}  // namespace

ExportResult ExportArduPilotParams(const Calibration& cal, const DriverScaleOptions& driver,
                                   const ExportContext& context) {
  const DiagonalCorrection c = ToDiagonalCorrection(cal, driver);
  ExportResult result;
  std::string& t = result.text;
  t += fmt::format("# ArduPilot accelerometer calibration by accelcal export-cal: {}.\n",
                   DescribeOrigin(cal, context));
  t += fmt::format("# Driver scaling assumed: (raw - {} counts) / {} counts per m/s^2 (x, y, z).\n",
                   fmt::format("{}/{}/{}", ExportNumber(driver.nominal_bias_counts.x()),
                               ExportNumber(driver.nominal_bias_counts.y()),
                               ExportNumber(driver.nominal_bias_counts.z())),
                   fmt::format("{}/{}/{}", ExportNumber(driver.nominal_scale_counts_per_mps2.x()),
                               ExportNumber(driver.nominal_scale_counts_per_mps2.y()),
                               ExportNumber(driver.nominal_scale_counts_per_mps2.z())));
  t += "# ArduPilot applies (accel - INS_ACCOFFS) * INS_ACCSCAL per sensor axis\n"
       "# (AP_InertialSensor_Backend::_rotate_and_correct_accel). Misalignment not held.\n";
  for (int j = 0; j < 3; ++j)
    t += fmt::format("INS_ACCOFFS_{},{}\n", kAxes[j], ExportNumber9(c.offset_mps2(j)));
  for (int j = 0; j < 3; ++j)
    t += fmt::format("INS_ACCSCAL_{},{}\n", kAxes[j], ExportNumber9(c.scale(j)));
  AddDiagonalLimits(cal, c, "ArduPilot", &result);
  for (int j = 0; j < 3; ++j) {
    if (std::fabs(c.offset_mps2(j)) > kOffsetRangeMps2)
      result.notes.push_back(fmt::format(
          "INS_ACCOFFS_{} = {:.4g} m/s^2 is outside ArduPilot's range -3.5..3.5: check the nominal "
          "zero-g level and scale", kAxes[j], c.offset_mps2(j)));
    if (c.scale(j) < kScaleMin || c.scale(j) > kScaleMax)
      result.notes.push_back(fmt::format(
          "INS_ACCSCAL_{} = {:.4g} is outside ArduPilot's range 0.8..1.2: check the nominal scale",
          kAxes[j], c.scale(j)));
  }
  result.notes.push_back("INS_ACC_ID is not written: it identifies the sensor on the autopilot, "
                         "which the calibration cannot know");
  return result;
}

}  // namespace accelcal
