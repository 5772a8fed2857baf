#include "accelcal/app/device_history.h"

#include <memory>
#include <optional>
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
  SessionOpenOptions read_only;
  read_only.read_only = true;
  for (const SessionInfo& s : ListSessions(dir, {}).sessions) {
    const std::optional<Fixture> sensors = SessionStore::Open(s.path, read_only)->Sensors();
    if (sensors && sensors->sensors.size() > 1) {
      for (const FixtureSensor& sensor : sensors->sensors) known.insert(sensor.serial);
    } else if (!s.device.empty()) {
      known.insert(s.device);
    }
  }
  if (known.empty()) throw Error(fmt::format("no session of device {} in {}: no session there names a device", device, dir));
  throw Error(fmt::format("no session of device {} in {}; devices there: {}", device, dir, fmt::join(known, ", ")));
}

// What a session holds of `device`: its result (none: not finished).
struct SessionResultOf {
  std::optional<std::string> result;
};

// A session of `device`: one that names it as its device, or a session of several sensors
// (a fixture, issue 31) one of which has its serial: each sensor is its own device. Nothing when
// the session is not of the device.
std::optional<SessionResultOf> DeviceResultIn(const SessionInfo& info, const std::string& device,
                                              const SessionOpenOptions& read_only) {
  const std::unique_ptr<SessionStore> store = SessionStore::Open(info.path, read_only);
  if (const std::optional<Fixture> sensors = store->Sensors(); sensors && sensors->sensors.size() > 1) {
    for (std::size_t i = 0; i < sensors->sensors.size(); ++i)
      if (sensors->sensors[i].serial == device) return SessionResultOf{store->SensorResult(static_cast<int>(i))};
    return std::nullopt;
  }
  if (info.device != device) return std::nullopt;
  return SessionResultOf{store->Result()};
}

}  // namespace

DeviceHistory BuildDeviceHistory(const std::string& folder, const std::string& device) {
  const std::string dir = folder.empty() ? DefaultSessionDir() : folder;
  DeviceHistory h;
  h.device = device;
  h.dir = dir;
  SessionOpenOptions read_only;
  read_only.read_only = true;
  for (SessionInfo info : ListSessions(dir, {}).sessions) {
    const std::optional<SessionResultOf> of = DeviceResultIn(info, device, read_only);
    if (!of) continue;
    if (!of->result) {
      ++h.sessions_without_result;
      continue;
    }
    info.device = device;  // a fixture's sensor: its serial, not the fixture's name
    HistoryEntry entry{info, CalibrationFromJsonText(*of->result, info.path), {}};
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
