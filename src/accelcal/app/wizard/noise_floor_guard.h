// The wizard's noise floor, kept honest. Every stillness check of the session is a multiple of
// the floor (static_stability.h), so a floor measured while the bench shook lets every shaking
// capture through. Three guards:
//
// 1. Measured only on a still sensor (Judge, over the quiet period's samples): refused when any
//    axis is above max_ratio x the procedure's expected noise ("the sensor was not still while
//    the noise floor was measured: x 9.8 counts, over 2 x the 1.6 counts this sensor shows on
//    a still bench"), or when the quiet period itself drifts or jumps (its own trend and spike
//    checks against the floor it gives).
// 2. Re-checked against the static captures as they come (Recheck): a still capture whose std
//    is below the floor / kProvesTooHighRatio on an axis proves the floor too high there: it is
//    lowered to that capture's std.
// 3. Then every static capture judged with the old floor is judged again against the new one
//    (the same check, offline_stability.h's EvaluateStaticStability); those that fail now are
//    named, to be left out and captured again.
//
// Units: counts (per-axis std of raw readings).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/acquire/capture_engine/noise_floor.h"
#include "accelcal/acquire/capture_engine/static_stability.h"
#include "accelcal/base/capture.h"

namespace accelcal {

struct NoiseFloorJudgement {
  bool ok = false;
  std::string reason;  // why it was refused, in words; empty when ok
};

// A static capture that fails the lowered floor.
struct RejudgedCapture {
  int capture_id = 0;
  std::string reason;  // "not still: moving: x std 7.5 counts, limit 2.3 (noise floor lowered ...)"
};

struct NoiseFloorRecheck {
  bool lowered = false;
  NoiseFloor before, after;
  std::string note;  // "the noise floor proved too high: ... lowered to ..."; empty when not
  std::vector<RejudgedCapture> failing;
};

class NoiseFloorGuard {
 public:
  // A still capture below floor / this ratio on an axis proves the floor too high. With 200+
  // samples a std is known within ~5 %, so 1.5 is many standard errors away.
  static constexpr double kProvesTooHighRatio = 1.5;

  // `expected_counts`: the procedure's expected noise per axis (NaN: not stated); `max_ratio`
  // (> 1): how far above it a floor may be; `stability`: the session's stillness check.
  NoiseFloorGuard(const Eigen::Vector3d& expected_counts, double max_ratio,
                  const StaticStabilityOptions& stability);

  // Judges a quiet period's samples (at least 3, time-ordered); when ok, they give the floor.
  NoiseFloorJudgement Judge(const std::vector<Sample>& quiet);
  // A floor known from before (a resumed session's lowered floor): taken as it is.
  void Restore(const NoiseFloor& floor) { floor_ = floor; }
  // `latest`: a static capture just accepted. `judged_before`: every static capture of the
  // session still used (latest included). Lowers the floor when `latest` proves it too high,
  // and judges `judged_before` again.
  NoiseFloorRecheck Recheck(const Capture& latest, const std::vector<const Capture*>& judged_before);

  const std::optional<NoiseFloor>& floor() const { return floor_; }
  // "x 1.52  y 1.49  z 1.71 counts (quiet period of 2.0 s, 200 samples)"; empty without one.
  std::string Describe() const;
  void Forget() { floor_.reset(); }

 private:
  Eigen::Vector3d expected_counts_;
  double max_ratio_;
  StaticStabilityOptions stability_;
  std::optional<NoiseFloor> floor_;
};

}  // namespace accelcal
