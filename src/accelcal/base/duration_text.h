// Long times as the wizard shows them (records run for hours).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace accelcal {

// "03:12:05" for a time in s (rounded to the second; hours may exceed 24; negative -> 0).
std::string FormatClock(double seconds);
// "3 h 12 min", "12 min 5 s", "42 s" (rounded to the second; negative -> 0).
std::string FormatLongDuration(double seconds);
// A number of whole days as typed: "30d", "30 d", "30" (days), "6w" (weeks), "1y" (365 days);
// nullopt when it is not one (negative, a fraction, another unit: "3m" could be months or minutes).
std::optional<long> ParseDays(std::string_view text);

}  // namespace accelcal
