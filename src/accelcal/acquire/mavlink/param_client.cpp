#include "accelcal/acquire/mavlink/param_client.h"

#include <set>

#include <fmt/format.h>

#include "accelcal/acquire/source/wall_clock.h"
#include "accelcal/base/error.h"

namespace accelcal::mavlink {

void AwaitVehicle(Connection& link, const ParamExchange& exchange) {
  if (link.vehicle().known) return;
  link.Pump(exchange.vehicle_wait_s, [&] { return link.vehicle().known; });
  if (link.vehicle().known) return;
  std::string why = link.link_error().empty()
                        ? fmt::format("no vehicle's heartbeat on {} in {:.0f} s", link.LinkName(),
                                      exchange.vehicle_wait_s)
                        : link.link_error();
  throw Error(fmt::format("{}: check the link (port, baud rate, address) and that the vehicle is on",
                          why));
}

ParamReadResult ReadParams(Connection& link, const std::vector<std::string>& names,
                           const ParamExchange& exchange) {
  AwaitVehicle(link, exchange);
  ParamReadResult result;
  std::set<std::string> wanted(names.begin(), names.end());
  auto collect = [&](const Frame& frame, bool from_vehicle) {
    if (!from_vehicle || frame.message != kParamValue) return;
    ParamValue v = DecodeParamValue(frame.payload);
    if (wanted.erase(v.id) > 0) result.values[v.id] = std::move(v);
  };
  for (int round = 0; round < exchange.rounds && !wanted.empty(); ++round) {
    for (const std::string& name : wanted)
      link.Send(kParamRequestRead, EncodeParamRequestRead(link.target_system(), link.target_component(), name));
    link.Pump(exchange.round_s, [&] { return wanted.empty(); }, collect);
  }
  result.unanswered.assign(wanted.begin(), wanted.end());
  return result;
}

std::optional<ParamValue> SetParam(Connection& link, const std::string& name, float wire_value,
                                   std::uint8_t type, const ParamExchange& exchange) {
  AwaitVehicle(link, exchange);
  std::optional<ParamValue> echo;
  auto collect = [&](const Frame& frame, bool from_vehicle) {
    if (!from_vehicle || frame.message != kParamValue) return;
    ParamValue v = DecodeParamValue(frame.payload);
    if (v.id == name) echo = std::move(v);
  };
  for (int round = 0; round < exchange.rounds && !echo; ++round) {
    link.Send(kParamSet, EncodeParamSet(link.target_system(), link.target_component(), name,
                                        wire_value, type));
    link.Pump(exchange.round_s, [&] { return echo.has_value(); }, collect);
  }
  return echo;
}

}  // namespace accelcal::mavlink
