// What a calibration must reach, as the procedure states it ([target] in the procedure file,
// README "Procedures"): the expanded uncertainty U (k = 2) on bias, scale and misalignment, and
// what the planner (calibration/capture_plan.h) needs to turn it into capture lengths: the
// longest capture the procedure allows and the bench's handling time.
//
// A target is not a limit: [limits] says what the certificate accepts (U, k = 2), [target] what
// the plan aims for; a target looser than the limits would plan a session the certificate
// fails, and is refused (CheckTargetAgainstLimits).
//
// Units: in the names (mg of specific force, ppm of the scale, mrad, s).
#pragma once

#include <string>

#include "accelcal/base/sensor_model.h"
#include "accelcal/calibration/capture_plan.h"

namespace accelcal {

struct ProcedureLimits;  // procedure.h

struct ProcedureTarget {
  double bias_mg = kNaN;              // U(k=2) of each bias, mg (1 mg = 9.80665e-3 m/s^2)
  double scale_ppm = kNaN;            // U(k=2) of each scale over the scale, ppm
  double misalignment_mrad = kNaN;    // U(k=2) of each misalignment angle, mrad
  double max_capture_s = 60.0;        // no capture planned or run longer, s
  double pose_handling_s = 20.0;      // setting a prism pose or a turntable radius, s
  double mounting_s = 60.0;           // a turntable mounting (another axis on the radius), s

  bool Any() const;  // at least one of the three uncertainties stated
};

// The planner's target in the parameters' own units at the nominal sensor: a bias in mg is
// counts through the smallest nominal scale (the strictest), at standard gravity.
UncertaintyTarget ToUncertaintyTarget(const ProcedureTarget& target, const SensorModel& nominal);

// A stated target looser than its limit: the [target] key and why, in words.
struct TargetConflict {
  std::string key;      // "bias_mg", "scale_ppm", "misalignment_mrad"; empty: none
  std::string message;
};

// No conflict (empty key) when every stated target is within the limits (both U, k = 2); else the
// first that is not.
TargetConflict CheckTargetAgainstLimits(const ProcedureTarget& target, const ProcedureLimits& limits,
                                     const SensorModel& nominal);

}  // namespace accelcal
