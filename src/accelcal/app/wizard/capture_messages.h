// What a capture's state means for the technician at the bench, in plain words about the bench
// and the hands ("the bench was knocked: don't touch it; measuring again"), decided from the
// capture engine's reasons (acquire/capture_engine: the stillness checks "moving: ...",
// "drifting: ...", "spike: ...", the timeout "no stable capture within ..."); the statistics
// behind the words kept apart, for a detail line (line mode) or one key away (the TUI), never
// on the main line.
//
// The normal settling after the prism is let go is a wait, not a warning: for its first
// kNormalSettleS of sample time a sensor that is not yet still reads "still settling after you
// let go: wait" (waiting = true); past that, the cause is named (shaking, knocked, drifting).
#pragma once

#include <string>

#include "accelcal/acquire/capture_engine/capture_engine.h"

namespace accelcal {

struct CaptureMessage {
  std::string text;     // plain words about the bench, one line
  std::string detail;   // the statistics behind it (std, limits, sigmas, times); may be empty
  bool waiting = false; // a normal wait (settling after letting go): shown as waiting, not a warning
};

// Which stillness check failed first, in the order a technician can act on: a knock (a spike)
// explains a large std and trend too; a std above its limit (moving) explains a trend.
enum class StillnessCause { kNone, kKnocked, kMoving, kDrifting };

// From the engine's reason text (its checks' prefixes, "; "-joined): the first cause found in
// the order knocked, moving, drifting; kNone for any other reason.
StillnessCause CauseOfReason(const std::string& reason);

// How long settling after a placement is normal (the hand letting go, the settle window), s of
// sample time; past it, a sensor not yet still is a problem with a name.
inline constexpr double kNormalSettleS = 6.0;

// The running capture (static or turntable) as the technician should read it.
CaptureMessage DescribeCapture(const CaptureSnapshot& snap, bool turntable);

// A capture that ended without being accepted (`reason`: the engine's or the wall clock's,
// e.g. "no stable capture within 60 s: last problem: moving: x std 12 counts, limit 2.4"): plain
// words for a timeout on stillness, the reason itself otherwise (a wrong face, a mounting, a
// silent link are already said in words about the bench). `timeout_s`: the give-up time.
CaptureMessage DescribeEnded(const std::string& reason, double timeout_s);

// What to do at the bench when a capture was given up because the sensor was never still
// (`reason` as for DescribeEnded): stop what shakes or knocks it, or let it warm up; empty for
// any other reason.
std::string StillnessHint(const std::string& reason);

}  // namespace accelcal
