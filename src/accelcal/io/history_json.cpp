#include "accelcal/io/history_json.h"

#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/detail/json_values.h"

namespace accelcal {

nlohmann::json DeviceHistoryToJson(const DeviceHistory& h) {
  nlohmann::json j = {{"device", h.device}, {"dir", h.dir}, {"calibrations", nlohmann::json::array()},
                      {"sessions_without_calibration", h.sessions_without_result}};
    for (const HistoryEntry& e : h.entries) {
    nlohmann::json params = nlohmann::json::object();
    const auto p = e.calibration.model.ToVector(), s = e.calibration.uncertainty.ToVector();
    for (int i = 0; i < kNumBaseParameters; ++i) {
      nlohmann::json q = {{"value", p(i)}, {"sigma", detail::JsonNumber(s(i))}, {"unit", ParameterUnit(i)},
                          {"delta", nullptr}, {"sigma_combined", nullptr}, {"n_sigmas", nullptr},
                          {"changed", nullptr}};
      if (!e.moves.empty()) {
        const ParameterMove& m = e.moves[static_cast<size_t>(i)];
        q["delta"] = m.delta;
        q["sigma_combined"] = detail::JsonNumber(m.sigma_combined);
        q["n_sigmas"] = detail::JsonNumber(m.n_sigmas);
        q["changed"] = m.changed;
      }
      params[std::string(ParameterName(i))] = q;
    }
    j["calibrations"].push_back({{"session", e.session.name}, {"path", e.session.path},
                                 {"created_utc", e.session.created_utc}, {"parameters", params}});
  }
  return j;
}

std::string DeviceHistoryJsonText(const DeviceHistory& history) {
  return detail::JsonText(DeviceHistoryToJson(history)) + "\n";
}

}  // namespace accelcal
