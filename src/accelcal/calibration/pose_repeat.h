// A pose of the prism taken twice in one session (the standard procedure takes its first pose
// again at the end: a "repeat" step): what the reading moved between the two, against what the
// captures' own noise explains. The fit sees only that the two captures disagree; this says by
// how much, over how long, and whether it is more than noise: a drift or a wandering bias, a
// sensor not yet warm, hysteresis after the turntable, a scale that moved.
//
// The prism is set down again, never exactly as before: a placement a fraction of a degree off
// turns gravity between the axes (a first-order change of the horizontal axes' readings) but
// leaves its magnitude alone. So the move is measured along gravity: the change of the reading's
// magnitude through the rough model, sum_j u_j (x2_j - x1_j) / K_j, u the unit up halfway
// between the two captures' (a1 + a2 normalized: then u . (a2 - a1) = (|a2|^2 - |a1|^2) / |a1 + a2|,
// the magnitude's change itself), expressed in counts of the mean scale; a bias or a scale that
// changed moves it, a re-placement only through the rough model's own bias error (a turn of d rad
// by about d times that error). (The first capture's up alone also missed by g (1 - cos d): 0.2
// counts for the 2 deg between the prism and the stopped turntable's seat, beyond the noise of
// two 15 s captures.)
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal {

struct PoseRepeat {
  std::string label;        // the pose, as both captures are labelled
  int first_id = 0;         // the earlier capture
  int again_id = 0;         // the later one
  double elapsed_s = kNaN;  // between their middles, on the session's clock, s
  double moved_counts = 0.0;  // along gravity, later less earlier, counts of the mean scale
  // The standard deviation of that move that the two captures' noise alone gives, counts (each
  // capture's standard error of its mean, or of its settled reading).
  double noise_counts = 0.0;
  // The reading moved more than noise explains: |moved / noise| beyond 3.29 (one in a thousand
  // repeats of a sensor that moved not at all).
  bool beyond_noise = false;
};

// The comparison of `again` with `first`, two static captures of one pose, through the rough
// model `rough` (the datasheet's or a fit's).
PoseRepeat ComparePoseRepeat(const Capture& first, const Capture& again, const SensorModel& rough);

// Every pose a capture set holds more than once (static captures used by the fit, with the same
// label): each later capture of the pose against its first, in the captures' order. A pose taken
// again several times (between the turntable runs and at the end) gives its path over the
// session: each repeat's move and time since the first.
std::vector<PoseRepeat> FindPoseRepeats(const std::vector<Capture>& captures, const SensorModel& rough);

// "moved 3.1 counts along gravity in 14 min, more than its noise (0.3 counts) explains" or
// "moved 0.2 counts along gravity in 14 min, within its noise (0.3 counts)".
std::string DescribePoseRepeat(const PoseRepeat& repeat);

// The path of the pose of `repeats` labelled `label` (FindPoseRepeats' entries of one pose), for
// the report: "+z up, taken again 3 times, moved along gravity since the first time: +0.4 counts
// after 9 min, +3.1 counts after 18 min, +2.0 counts after 27 min (noise of each move about 0.3
// counts); at most 3.1 counts, more than noise explains". Empty when the pose was not repeated.
std::string DescribePoseRepeatPath(const std::vector<PoseRepeat>& repeats, const std::string& label);
// The labels of the poses `repeats` hold, in the order of their first repeat.
std::vector<std::string> RepeatedPoseLabels(const std::vector<PoseRepeat>& repeats);

// The verdict's sentence when a pose taken again moved more than noise explains and the fit does
// not explain it either: "limited by a pose that read differently when taken again: ..." (the
// pose's whole path when it was taken again more than once).
std::string PoseRepeatLimitWords(const std::vector<PoseRepeat>& repeats, const std::string& label);

}  // namespace accelcal
