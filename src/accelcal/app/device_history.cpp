#include "accelcal/app/device_history.h"

#include <cmath>
#include <limits>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "accelcal/base/error.h"

namespace accelcal {

ParameterMove MoveBetween(double previous, double previous_sigma, double value, double sigma) {
  ParameterMove m;
  m.delta = value - previous;
  m.sigma_combined = std::hypot(previous_sigma, sigma);
  m.n_sigmas = m.sigma_combined > 0.0 ? std::fabs(m.delta) / m.sigma_combined
               : m.delta == 0.0       ? 0.0
                                      : std::numeric_limits<double>::infinity();
  m.changed = m.n_sigmas > kChangedSigmas;
  return m;
}

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

DeviceHistory BuildDeviceHistory(const std::string& dir, const std::string& device) {
  DeviceHistory h;
  h.device = device;
  h.dir = dir;
  SessionFilter filter;
  filter.device = device;
  SessionOpenOptions read_only;
  read_only.read_only = true;
  for (const SessionInfo& info : ListSessions(dir, filter).sessions) {
    const std::optional<nlohmann::json> result = SessionStore::Open(info.path, read_only)->Result();
    if (!result) {
      ++h.sessions_without_result;
      continue;
    }
    HistoryEntry entry{info, CalibrationFromJson(*result, info.path), {}};
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

nlohmann::json DeviceHistoryToJson(const DeviceHistory& h) {
  nlohmann::json j = {{"device", h.device}, {"dir", h.dir}, {"calibrations", nlohmann::json::array()},
                      {"sessions_without_calibration", h.sessions_without_result}};
  auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  for (const HistoryEntry& e : h.entries) {
    nlohmann::json params = nlohmann::json::object();
    const auto p = e.calibration.model.ToVector(), s = e.calibration.uncertainty.ToVector();
    for (int i = 0; i < kNumBaseParameters; ++i) {
      nlohmann::json q = {{"value", p(i)}, {"sigma", number(s(i))}, {"unit", ParameterUnit(i)},
                          {"delta", nullptr}, {"sigma_combined", nullptr}, {"n_sigmas", nullptr},
                          {"changed", nullptr}};
      if (!e.moves.empty()) {
        const ParameterMove& m = e.moves[static_cast<size_t>(i)];
        q["delta"] = m.delta;
        q["sigma_combined"] = number(m.sigma_combined);
        q["n_sigmas"] = number(m.n_sigmas);
        q["changed"] = m.changed;
      }
      params[std::string(ParameterName(i))] = q;
    }
    j["calibrations"].push_back({{"session", e.session.name}, {"path", e.session.path},
                                 {"created_utc", e.session.created_utc}, {"parameters", params}});
  }
  return j;
}

}  // namespace accelcal
