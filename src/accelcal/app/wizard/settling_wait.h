// The wizard's settling wait (issue 29): before a static capture, how long the sensor still needs
// after it is set down, learnt from the session's captures so far. calibration/settling.h finds
// a share of each change of pose lagging it with a time constant tau; the next capture then
// waits, still and in its pose, until what is left of its own change of pose is within the
// capture's noise (CaptureRequest::settle_wait_s), and the screen says why, in bench words.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/acquire/capture_engine/capture_request.h"
#include "accelcal/base/capture.h"

namespace accelcal {

struct WizardSession;

struct SettlingWait {
  double wait_s = 0.0;  // from the first sample of the capture, s; 0: no wait needed
  std::string reason;   // what it waits for, in bench words
};

// The wait before a capture reading `expected_counts` (the new pose by the rough model), after
// `captured` (the session's accepted captures so far, in time order; the last one is the pose
// the sensor comes from). No wait while the captures show no settling (or are too few to tell);
// at most four settling times and two minutes.
SettlingWait PlanSettlingWait(std::vector<Capture> captured, const Eigen::Vector3d& expected_counts);

// `request` (a static capture of the session's current step) given the wait the session's
// captures call for: its settle_wait_s and reason, and its timeout lengthened by the wait.
void AddSettlingWait(const WizardSession& session, CaptureRequest& request);

}  // namespace accelcal
