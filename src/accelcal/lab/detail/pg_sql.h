// SQL fragments the lab store's queries share.
#pragma once

#include <string>

namespace accelcal::detail {

// `column` (a timestamptz) as UTC ISO 8601 text with milliseconds, "2026-03-01T14:05:09.123Z",
// the form the sessions use (base/utc_time.h); NULL stays NULL.
inline std::string IsoUtc(const std::string& column) {
  return "to_char(" + column + " AT TIME ZONE 'UTC', 'YYYY-MM-DD\"T\"HH24:MI:SS.MS\"Z\"')";
}

// `column` (a date or timestamptz) as "2026-03-01", UTC.
inline std::string IsoDate(const std::string& column) { return "to_char(" + column + ", 'YYYY-MM-DD')"; }

}  // namespace accelcal::detail
