// Wall-clock time as text for the store and for session file names.
#pragma once

#include <string>

namespace accelcal {

// Now, UTC, ISO 8601 with milliseconds: "2025-03-01T14:05:09.123Z".
std::string UtcNowIso8601();
// Now, UTC, for file names: "20250301T140509Z".
std::string UtcNowCompact();
// "2025-03-01T14:05:09.123Z" -> "2025-03-01 14:05:09": a stored UTC time as a listing shows it.
std::string ShortUtc(const std::string& iso);

}  // namespace accelcal
