// One capture the procedure asks for, and what the session already knows when it asks.
// Units: s for durations, m and rpm for the turntable (as entered), counts for the noise floor.
#pragma once

#include <string>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/acquire/capture_engine/noise_floor.h"
#include "accelcal/acquire/capture_engine/orientation_check.h"
#include "accelcal/acquire/capture_engine/turntable_stability.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal {

struct CaptureRequest {
  int id = 0;             // the capture's id in the session (> 0)
  CaptureKind kind = CaptureKind::kStatic;
  std::string label;      // free text, e.g. "z up"
  // Static: the pose asked for ("up" in the platform frame, and its name for messages).
  NamedPose expected{"+z", Eigen::Vector3d::UnitZ()};
  // Turntable: radius, rpm and mounting as entered.
  TurntableSetup turntable;
  double duration_s = 10.0;  // length of the capture, s; > 0
  double timeout_s = 60.0;   // give up when no capture is accepted this long after the first
                             // sample, s; > duration_s
  // > 0: the capture ends on this many samples, a count fixed before it starts (the capture
  // plan's stop rule, calibration/capture_stop_rule.h), not on duration_s; duration_s is then
  // the time it is expected to take (for the give-up and the time shown).
  long stop_samples = 0;
  // Static: capturing starts no earlier than this long after the first sample, however still
  // the sensor is, s (>= 0; 0: no wait): a sensor seen still settling after the session's
  // earlier changes of pose is given the time it needs (app/wizard/settling_wait.h). The
  // timeout must leave room for it and the capture.
  double settle_wait_s = 0.0;
  // What the wait is for, in bench words, said while it lasts.
  std::string settle_wait_reason;

  std::string Validate() const;
};

// What the session knows before this capture.
struct CaptureContext {
  // Roughly known scale and bias (datasheet, or the static captures' fit): enough for the
  // orientation and turntable checks, not a calibration.
  SensorModel rough_model;
  // Measured in the quiet period at the session's start, or given.
  NoiseFloor noise_floor;
  // Poses captured so far (a pose is not taken twice).
  std::vector<CapturedPose> captured;
  // The procedure's poses other than the faces, to name a wrong pose.
  std::vector<NamedPose> known_poses;

  std::string Validate() const;
};

}  // namespace accelcal
