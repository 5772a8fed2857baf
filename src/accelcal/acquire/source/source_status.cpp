#include "accelcal/acquire/source/source_status.h"

#include <cmath>

#include <fmt/format.h>

namespace accelcal {

std::string_view LinkStateToString(LinkState state) {
  switch (state) {
    case LinkState::kConnecting: return "connecting";
    case LinkState::kUp: return "up";
    case LinkState::kDead: return "dead";
    case LinkState::kEnded: return "ended";
  }
  return "unknown";
}

std::string SourceStatus::BriefReport() const {
  const std::string rate = std::isnan(rate_hz) ? "-" : fmt::format("{:.1f}", rate_hz);
  std::string line = fmt::format("{}, {} Hz, {} samples, {} malformed, {} gaps",
                                 LinkStateToString(link), rate, samples_total, malformed_lines,
                                 gaps);
  if (!link_error.empty()) line += " (" + link_error + ")";
  return line;
}

}  // namespace accelcal
