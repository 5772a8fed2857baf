// The wall clock the sources pace and time out by: a steady (monotonic) clock, in s from an
// arbitrary origin. Internal to the sources.
#pragma once

namespace accelcal::source_detail {

// Seconds on the steady clock.
double WallNowS();
// Sleeps for duration_s (nothing when <= 0).
void SleepS(double duration_s);

// A source paced by the clock (the sim source, a replay paced by t) delivers at least this far
// apart (a read's timeout may come sooner), in bursts as a live link delivers a fast stream (USB
// frames, TCP segments): one sample per wake-up at 10 kHz cost its reader, the wizard's loop, a
// quarter of a core (issue 18). 5 ms is 50 samples at 10 kHz, one at 100 Hz, and no delay a
// person could see.
inline constexpr double kMinPacedBurstS = 0.005;

}  // namespace accelcal::source_detail
