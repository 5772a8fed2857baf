#include "accelcal/app/wizard/noise_floor_guard.h"

#include <cmath>

#include <fmt/core.h>

namespace accelcal {
namespace {

std::string Triad(const Eigen::Vector3d& v) {
  return fmt::format("x {:.2f}  y {:.2f}  z {:.2f}", v.x(), v.y(), v.z());
}

}  // namespace

NoiseFloorGuard::NoiseFloorGuard(const Eigen::Vector3d& expected_counts, double max_ratio,
                                 const StaticStabilityOptions& stability)
    : expected_counts_(expected_counts), max_ratio_(max_ratio), stability_(stability) {}

NoiseFloorJudgement NoiseFloorGuard::Judge(const std::vector<Sample>& quiet) {
  const CaptureStats stats = ComputeStats(quiet);
  const NoiseFloor measured = NoiseFloor::FromQuietPeriod(stats);
  const Eigen::Vector3d std_counts = measured.std_counts;
  for (int axis = 0; axis < 3; ++axis) {
    const double expected = expected_counts_[axis];
    if (!std::isfinite(expected) || !(std_counts[axis] > max_ratio_ * expected)) continue;
    return {false, fmt::format("the sensor was not still while the noise floor was measured: "
                               "{} counts of noise, over {:g} x the {} counts this sensor shows "
                               "on a still bench (the procedure's expected noise)",
                               Triad(std_counts), max_ratio_, Triad(expected_counts_))};
  }
  // Its own drift and jumps, against the floor it would give (the std check is moot there).
  const StabilityVerdict own = EvaluateStaticStability(quiet, measured, stability_);
  if (own.judged && !own.stable)
    return {false, "the sensor was not still while the noise floor was measured: " + own.reason};
  floor_ = measured;
  return {true, ""};
}

NoiseFloorRecheck NoiseFloorGuard::Recheck(const Capture& latest,
                                           const std::vector<const Capture*>& judged_before) {
  NoiseFloorRecheck out;
  if (!floor_ || latest.kind != CaptureKind::kStatic || latest.stats().n < 2) return out;
  out.before = *floor_;
  const Eigen::Vector3d latest_std = latest.stats().StdCounts();
  NoiseFloor lowered = *floor_;
  for (int axis = 0; axis < 3; ++axis) {
    if (latest_std[axis] * kProvesTooHighRatio < floor_->std_counts[axis]) {
      lowered.std_counts[axis] = latest_std[axis];
      out.lowered = true;
    }
  }
  if (!out.lowered) return out;
  lowered.source = fmt::format("lowered by capture {} ({})", latest.id, latest.label);
  floor_ = lowered;
  out.after = lowered;
  out.note = fmt::format("the noise floor proved too high: capture {} ({}) was still with {} counts "
                         "where the floor said {}: lowered to {} counts",
                         latest.id, latest.label, Triad(latest_std), Triad(out.before.std_counts),
                         Triad(lowered.std_counts));
  for (const Capture* c : judged_before) {
    if (c == nullptr || c->kind != CaptureKind::kStatic) continue;
    const StabilityVerdict v = EvaluateStaticStability(c->samples, lowered, stability_);
    if (v.judged && !v.stable) out.failing.push_back({c->id, "not still: " + v.reason});
  }
  return out;
}

std::string NoiseFloorGuard::Describe() const {
  if (!floor_) return "";
  return fmt::format("{} counts, {}", Triad(floor_->std_counts), floor_->source);
}

}  // namespace accelcal
