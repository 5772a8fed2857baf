// Building a device's calibration history (report/device_history.h) from the sessions of one
// directory: every session of the device that has a calibration, in order of creation. Each
// sensor of a session of several (a fixture, docs/fixtures.md) is a device of its own, known by
// its serial: its calibration in that session is an entry of its history.
#pragma once

#include <string>

#include "accelcal/report/device_history.h"

namespace accelcal {

// `dir` empty: the default session folder (session_paths.h). Throws accelcal::Error when the
// directory does not exist, or when it has no calibration of `device`: the message lists the
// devices that have sessions there (or says none do) and, for a known device without a
// finished calibration, how many sessions it has.
DeviceHistory BuildDeviceHistory(const std::string& dir, const std::string& device);

}  // namespace accelcal
