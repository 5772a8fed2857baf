// The MAVLink parameter protocol, the parts a calibration needs: read parameters by name
// (PARAM_REQUEST_READ, answered by PARAM_VALUE) and set one (PARAM_SET, echoed by PARAM_VALUE
// with the value the vehicle now holds). Requests go again to a vehicle that did not answer
// (a lost frame), a bounded number of times; then the parameter is reported as unanswered.
// Nothing here decides what to write: app/device/ does.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "accelcal/acquire/mavlink/mavlink_connection.h"

namespace accelcal::mavlink {

struct ParamExchange {
  double round_s = 0.7;  // one round of requests waits this long for answers
  int rounds = 4;        // rounds before a parameter counts as unanswered
  double vehicle_wait_s = 5.0;  // for the vehicle's first heartbeat
};

struct ParamReadResult {
  std::map<std::string, ParamValue> values;  // by name, as answered
  std::vector<std::string> unanswered;       // asked `rounds` times, never answered
};

// Waits for the vehicle's heartbeat (the target of the requests). Throws accelcal::Error naming
// the link when none comes within exchange.vehicle_wait_s.
void AwaitVehicle(Connection& link, const ParamExchange& exchange);

// Reads `names` (up to 16 characters each). Throws accelcal::Error when no vehicle answers the
// link at all (AwaitVehicle).
ParamReadResult ReadParams(Connection& link, const std::vector<std::string>& names,
                           const ParamExchange& exchange = {});

// Sends PARAM_SET and waits for its echo: the PARAM_VALUE of that name, which holds what the
// vehicle now stores (possibly not what was sent). nullopt: no echo after every round.
std::optional<ParamValue> SetParam(Connection& link, const std::string& name, float wire_value,
                                   std::uint8_t type, const ParamExchange& exchange = {});

}  // namespace accelcal::mavlink
