#include "accelcal/app/wizard/capture_messages.h"

#include <fmt/core.h>

namespace accelcal {
namespace {

bool HasCheck(const std::string& reason, const char* prefix) {
  // The checks' reasons are joined by "; "; each starts with its name.
  const std::string p(prefix);
  return reason.rfind(p, 0) == 0 || reason.find("; " + p) != std::string::npos ||
         reason.find(": " + p) != std::string::npos;
}

// Static, not yet capturing: what keeps it from starting, once settling is past normal.
std::string NotStillYet(StillnessCause cause) {
  switch (cause) {
    case StillnessCause::kKnocked: return "the bench was knocked: don't touch it; waiting for it to be still";
    case StillnessCause::kMoving:
      return "the bench is shaking: hands off, stop what shakes it; waiting for it to be still";
    case StillnessCause::kDrifting:
      return "the sensor is drifting (warming up, or the mount is settling): wait; it starts by itself "
             "once steady";
    case StillnessCause::kNone: break;
  }
  return "waiting for the sensor to be still";
}

// Static, a capture interrupted: why, and that it measures again by itself.
std::string Interrupted(StillnessCause cause) {
  switch (cause) {
    case StillnessCause::kKnocked: return "the bench was knocked: don't touch it; measuring again";
    case StillnessCause::kMoving: return "the sensor moved during the capture: hands off the bench; measuring again";
    case StillnessCause::kDrifting:
      return "the sensor is drifting (warming up, or the mount is settling): wait; measuring again "
             "once it is steady";
    case StillnessCause::kNone: break;
  }
  return "the capture was interrupted: hands off the bench; measuring again";
}

std::string GaveUpBecause(StillnessCause cause) {
  switch (cause) {
    case StillnessCause::kKnocked: return "the bench kept being knocked or shaken";
    case StillnessCause::kMoving: return "the bench kept shaking";
    case StillnessCause::kDrifting: return "the sensor kept drifting";
    case StillnessCause::kNone: break;
  }
  return "the sensor was never still long enough";
}

CaptureMessage DescribeStatic(const CaptureSnapshot& snap) {
  const std::string& live = snap.stability.reason;
  switch (snap.state) {
    case CaptureState::kCapturing: return {"keep hands off the bench", "", false};
    case CaptureState::kRetrying: return {Interrupted(CauseOfReason(snap.reason)), snap.reason, false};
    case CaptureState::kSettling: {
      if (!snap.settle_wait.empty()) return {snap.settle_wait, "", true};
      const StillnessCause cause = snap.stability.judged ? CauseOfReason(live) : StillnessCause::kNone;
      if (snap.elapsed_s < kNormalSettleS || cause == StillnessCause::kNone)
        return {"still settling after you let go: wait", live, true};
      return {NotStillYet(cause), live, false};
    }
    default: return {snap.reason, "", false};
  }
}

CaptureMessage DescribeTurntable(const CaptureSnapshot& snap) {
  switch (snap.state) {
    case CaptureState::kCapturing: return {"turning steadily; keep hands off the table", "", false};
    case CaptureState::kRetrying:
      return {"the run was disturbed: hands off the table; measuring again", snap.reason, false};
    case CaptureState::kSettling:
      if (snap.elapsed_s < kNormalSettleS || snap.reason.empty())
        return {"waiting for the table to turn steadily", snap.reason, true};
      return {"the table does not turn steadily yet: wait; check it runs at the speed entered",
              snap.reason, false};
    default: return {snap.reason, "", false};
  }
}

}  // namespace

StillnessCause CauseOfReason(const std::string& reason) {
  if (HasCheck(reason, "spike:")) return StillnessCause::kKnocked;
  if (HasCheck(reason, "moving:")) return StillnessCause::kMoving;
  if (HasCheck(reason, "drifting:")) return StillnessCause::kDrifting;
  return StillnessCause::kNone;
}

CaptureMessage DescribeCapture(const CaptureSnapshot& snap, bool turntable) {
  return turntable ? DescribeTurntable(snap) : DescribeStatic(snap);
}

std::string StillnessHint(const std::string& reason) {
  if (reason.rfind("no stable capture within", 0) != 0) return "";
  switch (CauseOfReason(reason)) {
    case StillnessCause::kKnocked:
    case StillnessCause::kMoving:
      return "find what shakes or knocks the bench (a hand or cable on it, a pump or fan, a door, "
             "footsteps) and stop it; Enter tries again";
    case StillnessCause::kDrifting:
      return "let the sensor warm up and the mount settle for a few minutes; Enter tries again";
    case StillnessCause::kNone: break;
  }
  return "";
}

CaptureMessage DescribeEnded(const std::string& reason, double timeout_s) {
  // A timeout on stillness: the engine's "no stable capture within T s: last problem: ...".
  // A silent link ("... (wall clock): no samples for 60 s") is already said in words.
  if (reason.rfind("no stable capture within", 0) != 0 || reason.find("no samples") != std::string::npos)
    return {reason, "", false};
  return {fmt::format("gave up after {:g} s: {}", timeout_s, GaveUpBecause(CauseOfReason(reason))),
          reason, false};
}

}  // namespace accelcal
