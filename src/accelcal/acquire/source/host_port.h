// HOST:PORT as the network specs write it (tcp:HOST:PORT, and the MAVLink links tcp:, udp:,
// udpout:): HOST a name or an address, IPv6 in brackets ([::1]:5760), PORT 1..65535.
#pragma once

#include <string>

namespace accelcal {

struct HostPort {
  std::string host;  // without brackets
  int port = 0;

  // "127.0.0.1:5760", "[::1]:5760".
  std::string Describe() const;
};

// Takes `text` (the part after the scheme) apart. Throws accelcal::Error naming `spec` (the whole
// spec, for the message) and showing `example` when it is malformed. any_port: port 0 (a
// listener's "any free port") is accepted.
HostPort ParseHostPort(const std::string& text, const std::string& spec, const std::string& example,
                       bool any_port = false);

}  // namespace accelcal
