// Export of a calibration as a PX4 parameter file in QGroundControl's format: CAL_ACC0_XOFF,
// _YOFF, _ZOFF (m/s^2) and CAL_ACC0_XSCALE, _YSCALE, _ZSCALE (dimensionless), the per-axis
// correction of diagonal_correction.h, which PX4 applies in the sensor frame before rotating to
// the body frame (src/lib/sensor_calibration/Accelerometer.hpp, Correct():
// rotation * ((data - thermal_offset - offset) .* scale)).
//
// File format (QGroundControl "Save to file"): `#` comment lines, then one line per parameter,
// tab-separated: vehicle id, component id, name, value, MAVLink type (9 = REAL32, 6 = INT32).
//
// CAL_ACC0_ID, the device id of the sensor on the autopilot, cannot be known from a bench
// calibration; PX4 applies CAL_ACCn_* only to the sensor whose device id matches, so without it
// the parameters are ignored. It is written only when given (`device_id`), else reported.
// Cannot hold: the misalignment and the sensor effects (PX4's thermal calibration, TC_A*, is a
// polynomial of its own).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "accelcal/io/export/diagonal_correction.h"
#include "accelcal/io/export/export_result.h"

namespace accelcal {

struct Px4ExportOptions {
  DriverScaleOptions driver;
  std::optional<std::int64_t> device_id;  // CAL_ACC0_ID when known (an INT32 parameter)

  // Empty when valid: the driver's figures, a device id that fits in an INT32.
  std::string Validate() const;
};

// Throws accelcal::Error when `options.driver` is invalid or an effect is unknown.
ExportResult ExportPx4Params(const Calibration& cal, const Px4ExportOptions& options,
                             const ExportContext& context);

}  // namespace accelcal
