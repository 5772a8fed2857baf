#include "accelcal/base/duration_text.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

namespace accelcal {

std::string FormatClock(double seconds) {
  const long s = std::isfinite(seconds) ? std::lround(std::max(0.0, seconds)) : 0;
  return fmt::format("{:02d}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60);
}

std::string FormatLongDuration(double seconds) {
  const long s = std::isfinite(seconds) ? std::lround(std::max(0.0, seconds)) : 0;
  if (s >= 3600) return fmt::format("{} h {} min", s / 3600, (s / 60) % 60);
  if (s >= 60) return fmt::format("{} min {} s", s / 60, s % 60);
  return fmt::format("{} s", s);
}

}  // namespace accelcal
