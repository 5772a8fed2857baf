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

std::optional<long> ParseDays(std::string_view text) {
  size_t i = 0;
  long value = 0;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
    if (value > 1'000'000) return std::nullopt;  // beyond any recalibration window
    value = value * 10 + (text[i++] - '0');
  }
  if (i == 0) return std::nullopt;
  while (i < text.size() && text[i] == ' ') ++i;
  const std::string_view unit = text.substr(i);
  if (unit.empty() || unit == "d" || unit == "day" || unit == "days") return value;
  if (unit == "w" || unit == "week" || unit == "weeks") return value * 7;
  if (unit == "y" || unit == "year" || unit == "years") return value * 365;
  return std::nullopt;
}

}  // namespace accelcal
