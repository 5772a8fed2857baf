// A device's calibration history (built by app/device_history.h, written as JSON by
// io/history_json.h): every session of the device (in one directory) that has a
// calibration, in order of creation, and how far each of the nine parameters (sensor_model.h)
// moved from one calibration to the next.
//
// A move is judged against the combined 1-sigma of the two calibrations,
// sigma = sqrt(sigma_prev^2 + sigma_this^2) (independent fits): |delta| > 3 sigma is "changed"
// (a move that noise explains with probability about 0.3 % per parameter, normal errors).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "accelcal/calibration/calibration.h"
#include "accelcal/session/session_catalog.h"

namespace accelcal {

inline constexpr double kChangedSigmas = 3.0;

struct ParameterMove {
  double delta = 0.0;           // this - previous, in the parameter's unit
  double sigma_combined = 0.0;  // sqrt(sigma_prev^2 + sigma_this^2)
  double n_sigmas = 0.0;        // |delta| / sigma_combined (inf when sigma is 0 and delta is not)
  bool changed = false;         // n_sigmas > kChangedSigmas
};

struct HistoryEntry {
  SessionInfo session;
  Calibration calibration;
  // Moves since the previous entry, in ParameterIndex order; empty for the first entry.
  std::vector<ParameterMove> moves;
};

struct DeviceHistory {
  std::string device;
  std::string dir;
  std::vector<HistoryEntry> entries;  // by creation time
  long sessions_without_result = 0;   // sessions of the device with no calibration yet
};

ParameterMove MoveBetween(double previous, double previous_sigma, double value, double sigma);

}  // namespace accelcal
