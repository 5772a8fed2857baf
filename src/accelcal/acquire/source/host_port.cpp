#include "accelcal/acquire/source/host_port.h"

#include <fmt/format.h>

#include "accelcal/base/error.h"
#include "accelcal/base/text_scan.h"

namespace accelcal {

std::string HostPort::Describe() const {
  const bool v6 = host.find(':') != std::string::npos;
  return v6 ? fmt::format("[{}]:{}", host, port) : fmt::format("{}:{}", host, port);
}

HostPort ParseHostPort(const std::string& text, const std::string& spec, const std::string& example,
                       bool any_port) {
  const size_t colon = text.rfind(':');
  HostPort hp{text.substr(0, colon), 0};
  if (hp.host.size() >= 2 && hp.host.front() == '[' && hp.host.back() == ']')
    hp.host = hp.host.substr(1, hp.host.size() - 2);
  if (colon == std::string::npos || hp.host.empty())
    throw Error(fmt::format("source '{}': expected {}", spec, example));
  long port = 0;
  if (!detail::ParseLong(text.substr(colon + 1), &port) || port < (any_port ? 0 : 1) || port > 65535)
    throw Error(fmt::format("source '{}': port '{}' is not a number in {}..65535", spec,
                            text.substr(colon + 1), any_port ? 0 : 1));
  hp.port = static_cast<int>(port);
  return hp;
}

}  // namespace accelcal
