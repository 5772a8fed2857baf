// A pose of the prism taken twice in one session (the standard procedure takes its first pose
// again at the end: a "repeat" step): what the reading moved between the two, against what the
// captures' own noise explains. The fit sees only that the two captures disagree; this says by
// how much, over how long, and whether it is more than noise: a drift or a wandering bias, a
// sensor not yet warm, hysteresis after the turntable, a prism or a mount that moved.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"

namespace accelcal {

struct PoseRepeat {
  std::string label;           // the pose, as both captures are labelled
  int first_id = 0;            // the earlier capture
  int again_id = 0;            // the later one
  double elapsed_s = kNaN;     // between their middles, on the session's clock, s
  Eigen::Vector3d moved_counts = Eigen::Vector3d::Zero();  // later reading less the earlier one
  // The standard deviation of that difference that the two captures' noise alone gives, per
  // axis, counts (each capture's standard error of its mean, or of its settled reading).
  Eigen::Vector3d noise_counts = Eigen::Vector3d::Zero();
  double chi2 = 0.0;  // sum over the axes of (moved / noise)^2: 3 degrees of freedom
  // The reading moved more than noise explains (chi2 beyond chi-square's 0.999 quantile at 3
  // degrees of freedom, 16.27: one in a thousand repeats of a sensor that moved not at all).
  bool beyond_noise = false;
};

// The comparison of `again` with `first`, two static captures of one pose.
PoseRepeat ComparePoseRepeat(const Capture& first, const Capture& again);

// Every pose a capture set holds more than once (static captures used by the fit, with the same
// label): the latest capture of the pose against its first, in the order of the latest.
std::vector<PoseRepeat> FindPoseRepeats(const std::vector<Capture>& captures);

// "moved 3.1 counts in 14 min, more than its noise (0.3 counts) explains" or "moved 0.2 counts
// in 14 min, within its noise (0.3 counts)": the largest axis' move, in bench words.
std::string DescribePoseRepeat(const PoseRepeat& repeat);

// The verdict's sentence when a pose taken again moved more than noise explains and the fit does
// not explain it either: "limited by a pose that read differently when taken again: ...".
std::string PoseRepeatLimitWords(const PoseRepeat& repeat);

}  // namespace accelcal
