// Long times as the wizard shows them (records run for hours).
#pragma once

#include <string>

namespace accelcal {

// "03:12:05" for a time in s (rounded to the second; hours may exceed 24; negative -> 0).
std::string FormatClock(double seconds);
// "3 h 12 min", "12 min 5 s", "42 s" (rounded to the second; negative -> 0).
std::string FormatLongDuration(double seconds);

}  // namespace accelcal
