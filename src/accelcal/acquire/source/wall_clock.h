// The wall clock the sources pace and time out by: a steady (monotonic) clock, in s from an
// arbitrary origin. Internal to the sources.
#pragma once

namespace accelcal::source_detail {

// Seconds on the steady clock.
double WallNowS();
// Sleeps for duration_s (nothing when <= 0).
void SleepS(double duration_s);

}  // namespace accelcal::source_detail
