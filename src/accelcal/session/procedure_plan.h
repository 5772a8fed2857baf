// A procedure's captures as the planner sees them (calibration/capture_plan.h), and the plan of
// a session: each capture's length for the procedure's [target], from the sensor's noise (the
// floor measured at the start of the session, or the procedure's expected noise before it is).
//
// Which steps are captures is the step-kind table's (StepAcquires: a static or a turntable
// capture); nothing here names a kind. A step that is not required may be left out by the plan
// when it buys nothing for this sensor. Handling is the procedure's [target] (pose_handling_s per
// capture, mounting_s once per turntable mounting); settling the capture engine's windows.
//
// Units: s, counts (noise), Hz, m/s^2.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/calibration/capture_plan.h"
#include "accelcal/session/procedure.h"

namespace accelcal {

// The settling the capture engine waits before a capture counts (its settle windows), s.
inline constexpr double kPlannedStaticSettleS = 2.0;
inline constexpr double kPlannedTurntableSettleS = 3.0;
// The shortest capture planned: a static one long enough for its stillness check, a turntable
// run this many whole revolutions (its once-per-revolution swing is fitted and removed).
inline constexpr double kMinStaticCaptureS = 2.0;
inline constexpr double kMinTurntableRevolutions = 6.0;

// The planner's captures of `procedure` at `gravity_mps2`, in the steps' order; `fixed_s` > 0
// pins every capture to that length (the fixed plan, for comparison).
std::vector<PlannedCapture> PlannedCapturesOf(const Procedure& procedure, double gravity_mps2,
                                              double fixed_s = 0.0);

// The noise the plan assumes: the measured floor when there is one, else the procedure's
// expected noise, else 1 count.
PlannedSensor PlannedSensorOf(const Procedure& procedure, const std::optional<Eigen::Vector3d>& noise_counts,
                              double rate_hz);

struct SessionPlan {
  bool planned = false;       // the procedure states a target: `plan` holds the lengths
  CapturePlan plan;           // the plan (or, unplanned, the fixed lengths' times)
  PlannedSensor sensor;       // what it assumed
  // The same procedure with each step's own fixed duration: what the plan is compared with.
  CapturePlan fixed;
  // The parameters whose target the reference quantities' uncertainty alone exceeds (the local
  // gravity's, the ruler's, ...): no capture length reaches it, so the plan leaves it out and
  // reaches the others; empty when every target is reachable.
  std::vector<std::string> beyond_references;

  // The planned capture of step `id`; nullptr when the plan has none (not planned, not a
  // capture step, or left out).
  const PlannedLength* For(const std::string& step_id) const;
  // The plan leaves step `id` out: it buys nothing for this sensor.
  bool LeftOut(const std::string& step_id) const;
};

// The plan of `procedure` for the sensor's noise at `rate_hz`: by its [target] when it states
// one (and `fixed_duration_s` is 0), else each step's own duration (or `fixed_duration_s`).
SessionPlan PlanSession(const Procedure& procedure, const std::optional<Eigen::Vector3d>& noise_counts,
                        double rate_hz, double gravity_mps2, const ReferenceUncertainties& references,
                        double fixed_duration_s = 0.0);

// The noise the plan assumed differs enough from `measured_counts` to plan again (any axis off
// by more than 20 %).
bool NoiseDiffers(const Eigen::Vector3d& assumed_counts, const Eigen::Vector3d& measured_counts);

}  // namespace accelcal
