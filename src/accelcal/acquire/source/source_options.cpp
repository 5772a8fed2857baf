#include "accelcal/acquire/source/source_options.h"

#include <cmath>

#include <fmt/format.h>

namespace accelcal {

std::string SourceOptions::Validate() const {
  if (!(dead_after_s > 0.0) || !std::isfinite(dead_after_s))
    return fmt::format("dead_after_s = {} must be a positive number of seconds", dead_after_s);
  if (!(gap_factor > 1.0) || !std::isfinite(gap_factor))
    return fmt::format("gap_factor = {} must be greater than 1", gap_factor);
  if (!(reconnect_initial_s > 0.0) || !(reconnect_max_s >= reconnect_initial_s) ||
      !std::isfinite(reconnect_max_s))
    return fmt::format("reconnect back-off {} s .. {} s: need 0 < initial <= max",
                       reconnect_initial_s, reconnect_max_s);
  if (max_line_bytes < 64)
    return fmt::format("max_line_bytes = {} is too small (at least 64)", max_line_bytes);
  if (std::string e = format.Validate(); !e.empty()) return "format: " + e;
  if (stdin_fd < 0) return fmt::format("stdin_fd = {} is not a file descriptor", stdin_fd);
  return sim.Validate();
}

}  // namespace accelcal
