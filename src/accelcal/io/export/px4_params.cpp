#include "accelcal/io/export/px4_params.h"

#include <cstdint>

#include <fmt/format.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

constexpr const char* kPx4Axes[3] = {"X", "Y", "Z"};
constexpr int kMavParamTypeReal32 = 9;  // MAVLink MAV_PARAM_TYPE_REAL32
constexpr int kMavParamTypeInt32 = 6;   // MAVLink MAV_PARAM_TYPE_INT32

}  // namespace

std::string Px4ExportOptions::Validate() const {
  if (std::string why = driver.Validate(); !why.empty()) return why;
  if (device_id && (*device_id < INT32_MIN || *device_id > INT32_MAX))
    return fmt::format("the PX4 device id {} does not fit CAL_ACC0_ID (a 32-bit integer)", *device_id);
  return {};
}

ExportResult ExportPx4Params(const Calibration& cal, const Px4ExportOptions& options,
                             const ExportContext& context) {
  if (const std::string why = options.Validate(); !why.empty()) throw Error(why);
  const DiagonalCorrection c = ToDiagonalCorrection(cal, options.driver);
  ExportResult result;
  std::string& t = result.text;
  t += fmt::format("# PX4 accelerometer calibration by accelcal export-cal: {}.\n", DescribeOrigin(cal, context));
  t += "# PX4 applies (accel - CAL_ACC0_?OFF) .* CAL_ACC0_?SCALE per sensor axis\n"
       "# (sensor_calibration/Accelerometer.hpp). Misalignment not held.\n";
  t += "#\n# Vehicle-Id Component-Id Name Value Type\n";
  if (options.device_id)
    t += fmt::format("1\t1\tCAL_ACC0_ID\t{}\t{}\n", *options.device_id, kMavParamTypeInt32);
  for (int j = 0; j < 3; ++j)
    t += fmt::format("1\t1\tCAL_ACC0_{}OFF\t{}\t{}\n", kPx4Axes[j], ExportNumber9(c.offset_mps2(j)), kMavParamTypeReal32);
  for (int j = 0; j < 3; ++j)
    t += fmt::format("1\t1\tCAL_ACC0_{}SCALE\t{}\t{}\n", kPx4Axes[j], ExportNumber9(c.scale(j)), kMavParamTypeReal32);
  AddDiagonalLimits(cal, c, "PX4", &result);
  if (!options.device_id)
    result.cannot_hold.push_back(
        "CAL_ACC0_ID (the sensor's device id on the autopilot) cannot be known from the bench: "
        "PX4 applies CAL_ACC0_* only to the sensor with that id, so set it (e.g. from the "
        "autopilot's current CAL_ACC0_ID) or pass --px4-device-id");
  return result;
}

}  // namespace accelcal
