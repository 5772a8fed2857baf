#include "accelcal/app/device_history.h"

#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "accelcal/base/error.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/session/session_catalog.h"
#include "accelcal/session/session_paths.h"
#include "accelcal/session/session_store.h"

namespace accelcal {

namespace {

[[noreturn]] void NoCalibration(const std::string& dir, const std::string& device, long without_result) {
  if (without_result > 0)
    throw Error(fmt::format("device {} has {} session(s) in {} but none with a calibration yet",
                            device, without_result, dir));
  std::set<std::string> known;
  for (const SessionInfo& s : ListSessions(dir, {}).sessions)
    if (!s.device.empty()) known.insert(s.device);
  if (known.empty()) throw Error(fmt::format("no session of device {} in {}: no session there names a device", device, dir));
  throw Error(fmt::format("no session of device {} in {}; devices there: {}", device, dir, fmt::join(known, ", ")));
}

}  // namespace

DeviceHistory BuildDeviceHistory(const std::string& folder, const std::string& device) {
  const std::string dir = folder.empty() ? DefaultSessionDir() : folder;
  DeviceHistory h;
  h.device = device;
  h.dir = dir;
  SessionFilter filter;
  filter.device = device;
  SessionOpenOptions read_only;
  read_only.read_only = true;
  for (const SessionInfo& info : ListSessions(dir, filter).sessions) {
    const std::optional<std::string> result = SessionStore::Open(info.path, read_only)->Result();
    if (!result) {
      ++h.sessions_without_result;
      continue;
    }
    HistoryEntry entry{info, CalibrationFromJsonText(*result, info.path), {}};
    if (!h.entries.empty()) {
      const Calibration& prev = h.entries.back().calibration;
      const auto p0 = prev.model.ToVector(), s0 = prev.uncertainty.ToVector();
      const auto p1 = entry.calibration.model.ToVector(), s1 = entry.calibration.uncertainty.ToVector();
      for (int i = 0; i < kNumBaseParameters; ++i) entry.moves.push_back(MoveBetween(p0(i), s0(i), p1(i), s1(i)));
    }
    h.entries.push_back(std::move(entry));
  }
  if (h.entries.empty()) NoCalibration(dir, device, h.sessions_without_result);
  return h;
}

}  // namespace accelcal
