// How long things take, as the technician sees them: the seconds left of the running capture,
// the countdown to its give-up (the step's timeout_s), and an estimate of the session's time
// left from the procedure's remaining steps: each step's capture (or record) length plus a
// handling allowance (turning the prism, mounting the turntable, reading a result). It is an
// estimate and says so: the allowances are typical times at the bench, not measured ones.
//
// Units: s throughout.
#pragma once

#include <functional>
#include <string>

#include "accelcal/session/procedure.h"

namespace accelcal {

// Typical handling times per step, s. Why these values: turning the prism to a face and letting
// go takes a technician 10-20 s; the capture engine then needs its settle window (2 s, 3 s on
// the turntable) after the hand; mounting the sensor on the turntable, entering radius and
// speed and spinning up is about a minute; reading a fit or a report, half a minute.
struct TimeAllowances {
  double place_pose_s = 15.0;
  double settle_s = 3.5;           // letting go and the settle window
  double mount_turntable_s = 60.0;
  double level_s = 30.0;           // two readings, the prism turned between them
  double read_result_s = 20.0;     // fit, diagnosis, report, analysis
};

// One step from its start: its capture or record length plus its handling, s (its kind's
// estimate: step_registry.h).
double StepEstimateS(const ProcedureStep& step, const TimeAllowances& allowances = {});

// The steps from index `first` on (0-based; past the end: 0) that `done` does not say are done,
// s.
double RemainingEstimateS(const Procedure& procedure, int first,
                          const std::function<bool(const ProcedureStep&)>& done,
                          const TimeAllowances& allowances = {});

// "about 14 min", "about 40 s", "under 10 s": a rough figure for an estimate.
std::string FormatEstimate(double seconds);

// The time line of a capture screen, e.g.
//   "7 s left of this capture; gives up in 52 s; session: about 14 min left (estimate)"
// `capture_left_s` NaN: the capture has not started (its length is said instead, with
// `capture_s`); `give_up_in_s` NaN: no countdown (not shown).
std::string CaptureTimeText(double capture_s, double capture_left_s, double give_up_in_s,
                            double session_left_s);

// The time line of a screen that waits for the technician: "this capture takes 10 s once the
// sensor is still (gives up after 60 s); session: about 14 min left (estimate)". `capture_s`
// NaN: no capture on this step (only the session's estimate).
std::string WaitingTimeText(double capture_s, double timeout_s, double session_left_s);

// The time line of the last step's result (the report): the session is over once it is read.
std::string LastStepTimeText();

}  // namespace accelcal
