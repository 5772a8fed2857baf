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
  if (lost_frames > 0) line += fmt::format(", {} sample{} lost", lost_frames, lost_frames == 1 ? "" : "s");
  if (!link_error.empty()) line += " (" + link_error + ")";
  return line;
}

}  // namespace accelcal

namespace accelcal {

std::string SourceStatus::ResolutionNote() const {
  if (std::isnan(resolution_counts)) return {};
  const bool mg = !unit.is_counts() && std::fabs(resolution_counts - 9.80665) < 1e-9;
  return fmt::format("the readings come in steps of {:.3g} counts{}: a noise below {:.3g} counts (step / "
                     "sqrt 12) is the rounding, not the sensor; a quantised stream is not a quiet sensor",
                     resolution_counts, mg ? " (1 mG)" : "", resolution_counts / std::sqrt(12.0));
}

}  // namespace accelcal
