// tcp:HOST:PORT: a TCP connection to a sample server (e.g. a board piping its ADC as text
// lines). The connect is non-blocking (a slow or absent server never stalls Read past its
// timeout); a refused connection or a dropped one is retried by StreamSource with back-off.
// HOST is a name or an address (IPv4, or IPv6 in brackets: tcp:[::1]:5000); it is resolved
// again on every attempt, so a board that changes address is found.
#pragma once

#include <memory>
#include <string>

#include "accelcal/acquire/source/byte_link.h"

namespace accelcal {

std::unique_ptr<ByteLink> MakeTcpLink(const std::string& host, int port);

}  // namespace accelcal
