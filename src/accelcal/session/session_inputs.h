// What the operator answered and the wizard noted, as the journal keeps it
// (SessionJournal::RecordInput: a step id, a key, a text value), named here once: the welcome's
// answers (typed: WelcomeAnswers), the noise floor's figures, a turntable run's radius, speed,
// tilt and swing. Every reader and writer of these inputs takes the names from here.
#pragma once

#include <map>
#include <optional>
#include <string>

namespace accelcal {

// Step id -> key -> value, as the journal returns them.
using SessionInputs = std::map<std::string, std::map<std::string, std::string>>;

// ---- the welcome ----------------------------------------------------------------------------

// The welcome's pseudo step: its inputs are the session's identification, gravity and equipment.
inline constexpr const char* kWelcomeStepId = "welcome";

// The welcome's questions' keys. The device and the operator also fill the session's row
// (session_store.h), at whichever step records them.
namespace welcome_key {
inline constexpr const char* kDevice = "device";
inline constexpr const char* kOperator = "operator";
inline constexpr const char* kPlace = "place";
inline constexpr const char* kGravity = "gravity";
inline constexpr const char* kEquipment = "equipment";
// Not a question: what the source's device held when the session began (a MAVLink vehicle's own
// calibration and whether it was taken out of the readings), one fact per line.
inline constexpr const char* kDeviceCalibration = "device_calibration";
}  // namespace welcome_key

// The welcome's answers as recorded; nullopt: not answered (yet).
struct WelcomeAnswers {
  std::optional<std::string> device;         // the device's serial number
  std::optional<std::string> operator_name;
  std::optional<std::string> place;          // the lab or bench, as typed
  // The local gravity as it reads back (app/wizard/gravity_input.h parses it).
  std::optional<std::string> gravity;
  // The equipment as typed: "keep", or the items changed (app/wizard/equipment_input.h).
  std::optional<std::string> equipment;

  // The answer kept under `key` (a welcome_key); nullptr for another key.
  const std::optional<std::string>* Find(const std::string& key) const;
};

// The welcome's answers among `inputs`.
WelcomeAnswers ReadWelcomeAnswers(const SessionInputs& inputs);

// ---- the noise floor ------------------------------------------------------------------------

// The noise floor's pseudo step: the floor measured (per axis, counts: "x y z"), a floor the
// captures lowered with the note that says why, and, when the source's readings come in steps
// as coarse as the floor, what that resolution means for it (in words).
inline constexpr const char* kNoiseFloorStepId = "noise_floor";
namespace noise_floor_key {
inline constexpr const char* kStdCounts = "std_counts";
inline constexpr const char* kLoweredStdCounts = "lowered_std_counts";
inline constexpr const char* kLowered = "lowered";
inline constexpr const char* kResolution = "resolution";
}  // namespace noise_floor_key

// ---- a turntable run ------------------------------------------------------------------------

// Recorded at the run's step id beside its capture: the radius (m) and speed (rpm) it was taken
// at, the table's tilt (deg) and the once-per-revolution swing removed from its samples.
namespace turntable_key {
inline constexpr const char* kRadiusM = "radius_m";
inline constexpr const char* kRpm = "rpm";
inline constexpr const char* kTableTiltDeg = "table_tilt_deg";
inline constexpr const char* kSwingRemovedCounts = "swing_removed_counts";
}  // namespace turntable_key

// ---- bench time ---------------------------------------------------------------------------

// The capture plan's pseudo step (app/wizard/bench_plan.h): the plan the session ran by, its
// times (s) and the expanded uncertainty U (k = 2) it predicted for the nine parameters
// ("p1 ... p9" in ParameterIndex order, the parameters' units; "nan" where none), and whether
// it was planned by the procedure's [target] ("target") or fixed lengths ("fixed").
inline constexpr const char* kBenchPlanStepId = "bench_plan";
namespace bench_key {
inline constexpr const char* kPlannedBy = "planned_by";
inline constexpr const char* kPlannedCaptureS = "planned_capture_s";
inline constexpr const char* kPlannedSettleS = "planned_settle_s";
inline constexpr const char* kPlannedHandlingS = "planned_handling_s";
inline constexpr const char* kPlannedU = "planned_u";
inline constexpr const char* kTargetU = "target_u";
// Recorded at a capture's step id when it is accepted: the bench time it took, s (capture,
// settling and retries before it, handling: the bench's model on the virtual bench, else the
// time from the previous capture's end to this one's start).
inline constexpr const char* kCaptureS = "capture_s";
inline constexpr const char* kSettleS = "settle_s";
inline constexpr const char* kHandlingS = "handling_s";
}  // namespace bench_key

// ---- a write-back into the vehicle ----------------------------------------------------------

// Recorded at the write-back step's id: the PARAM_SETs it offered (one per line) and, when the
// technician said yes, what the vehicle held before, what was written and read back (or where
// it stopped), one fact per line.
namespace write_back_key {
inline constexpr const char* kPlanned = "planned";
inline constexpr const char* kOutcome = "outcome";
}  // namespace write_back_key

// ---- the session clock ------------------------------------------------------------------------

// The session clock's pseudo step (app/wizard/session_clock.h): the last accepted capture's t
// and wall time ("t wall", s), and each resume's shift ("resume 1", "resume 2", ...: in words).
inline constexpr const char* kSessionClockStepId = "session_clock";
namespace session_clock_key {
inline constexpr const char* kLastCapture = "last_capture";
inline constexpr const char* kResumePrefix = "resume ";
}  // namespace session_clock_key

// ---- a refit ------------------------------------------------------------------------------

// A refit of the finished session (app/refit_session.h) records at its step "refit N" (N from 1)
// when it ran (ISO 8601) and each change it made, "change 1", "change 2", ... ("gravity:
// standard -> 9.78030 +- 0.00001").
inline constexpr const char* kRefitStepPrefix = "refit ";
namespace refit_key {
inline constexpr const char* kAt = "at";
inline constexpr const char* kChangePrefix = "change ";
}  // namespace refit_key

}  // namespace accelcal
