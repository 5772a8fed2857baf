// A device's calibration history (device_history.h) as text for a terminal: per calibration, its
// date and session, then each of the nine parameters with its 1-sigma and how far it moved since
// the previous calibration (in its unit and in sigmas), flagged "changed" beyond kChangedSigmas.
// The same figures as the history's JSON (io/history_json.h).
#pragma once

#include <string>

#include "accelcal/report/device_history.h"

namespace accelcal {

std::string FormatHistoryText(const DeviceHistory& history);

}  // namespace accelcal
