// The local gravity as the operator types it at the wizard's welcome (or gives it on the command
// line): one of
//   "9.7803"                    a measured value, m/s^2; its uncertainty the resolution typed
//   "9.78030 +- 0.00002"        a measured value with its standard uncertainty ("±" too; an
//                               optional unit m/s^2 after either number)
//   "lat -34.9 alt 43"          WGS84 normal gravity at a latitude (deg) and altitude (m above
//                               the ellipsoid; 0 when left out); "latitude", "altitude", and the
//                               units "deg", "m" are accepted; commas are blanks
//   "standard"                  the standard 9.80665 m/s^2, said explicitly: a convention, not
//                               the local value (its uncertainty is large; see gravity.h)
// and refuses anything else with the reason in words. A procedure may refuse the standard value
// (Procedure::require_local_gravity): the session then needs a measured value or a location.
#pragma once

#include <string>
#include <string_view>

#include "accelcal/base/gravity.h"

namespace accelcal {

struct GravityAnswer {
  GravitySpec gravity;  // valid when error is empty
  std::string error;    // why the text was refused
  bool ok() const { return error.empty(); }
};

GravityAnswer ParseGravityAnswer(std::string_view text);

// How a spec is typed back (the wizard's default answer, and what the session records so that a
// resume reads the same gravity): "standard", "9.78030 +- 0.00002", "lat -34.9 alt 43".
std::string GravityAnswerText(const GravitySpec& gravity);

}  // namespace accelcal
