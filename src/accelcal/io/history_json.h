// A device's calibration history (report/device_history.h) as JSON (`accelcal history --format
// json`):
//   {"device", "dir", "calibrations": [{"session", "path", "created_utc", "parameters":
//   {"bias_x": {"value", "sigma", "unit", "delta", "sigma_combined", "n_sigmas", "changed"}, ..}}],
//    "sessions_without_calibration"}
// (the move fields are null for the first calibration).
#pragma once

#include <string>

#include "accelcal/report/device_history.h"

namespace accelcal {

// The JSON text (2-space indent, a final newline).
std::string DeviceHistoryJsonText(const DeviceHistory& history);

}  // namespace accelcal
