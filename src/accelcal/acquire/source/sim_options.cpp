#include "accelcal/acquire/source/sim_options.h"

#include <cmath>

#include <fmt/format.h>

namespace accelcal {

std::string SimOptions::Validate() const {
  if (!std::isfinite(speed) || (speed != 0.0 && speed < 1.0))
    return fmt::format("speed = {}: expected 0 (as fast as possible) or >= 1 (1 = real time)",
                       speed);
  if (!(fast_chunk_s > 0.0) || !std::isfinite(fast_chunk_s))
    return fmt::format("fast_chunk_s = {} must be a positive number of seconds", fast_chunk_s);
  if (!std::isnan(placement_error_deg) && !(placement_error_deg >= 0.0 && placement_error_deg <= 45.0))
    return fmt::format("placement_error_deg = {} must be within 0..45 deg", placement_error_deg);
  if (!(bump_probability >= 0.0 && bump_probability <= 1.0))
    return fmt::format("bump_probability = {} must be within 0..1", bump_probability);
  if (!(settle_s >= 0.0) || !std::isfinite(settle_s))
    return fmt::format("settle_s = {} must be a non-negative number of seconds", settle_s);
  return {};
}

}  // namespace accelcal
