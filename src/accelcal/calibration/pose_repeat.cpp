#include "accelcal/calibration/pose_repeat.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

namespace accelcal {
namespace {

// |z| beyond this: one in a thousand, two-sided.
constexpr double kLimitZ = 3.29;

// The capture's reading and its standard error per axis, counts: its settled reading when it was
// still settling (calibration/settling.h), else its mean.
void ReadingOf(const Capture& c, Eigen::Vector3d& mean_counts, Eigen::Vector3d& se_counts) {
  if (c.settled) {
    mean_counts = c.settled->mean_counts;
    se_counts = c.settled->mean_cov_counts2.diagonal().cwiseMax(0.0).cwiseSqrt();
    return;
  }
  mean_counts = c.stats().mean_counts;
  se_counts = c.stats().MeanCovariance().diagonal().cwiseMax(0.0).cwiseSqrt();
}

// "14 min", "45 s", "2 h 5 min".
std::string ElapsedWords(double s) {
  if (!std::isfinite(s)) return "";
  if (s < 90.0) return fmt::format("{:.0f} s", s);
  const long min = std::lround(s / 60.0);
  if (min < 120) return fmt::format("{} min", min);
  return fmt::format("{} h {} min", min / 60, min % 60);
}

}  // namespace

PoseRepeat ComparePoseRepeat(const Capture& first, const Capture& again, const SensorModel& rough) {
  PoseRepeat r;
  r.label = again.label;
  r.first_id = first.id;
  r.again_id = again.id;
  r.elapsed_s = again.stats().mean_t_s - first.stats().mean_t_s;
  Eigen::Vector3d m1, s1, m2, s2;
  ReadingOf(first, m1, s1);
  ReadingOf(again, m2, s2);
  const Eigen::Vector3d scale = rough.scale_counts_per_mps2;
  // Halfway between the two ups: a turn between the captures moves nothing (pose_repeat.h).
  const Eigen::Vector3d up = (rough.Calibrate(m1).normalized() + rough.Calibrate(m2).normalized()).normalized();
  // Per axis, counts of the mean scale per count of the axis: u_j K_mean / K_j.
  const Eigen::Vector3d weight = up.cwiseProduct(scale.cwiseInverse()) * scale.mean();
  r.moved_counts = weight.dot(m2 - m1);
  r.noise_counts = std::sqrt(weight.cwiseAbs2().dot(s1.cwiseAbs2() + s2.cwiseAbs2()));
  r.beyond_noise = r.noise_counts > 0.0 && std::abs(r.moved_counts) > kLimitZ * r.noise_counts;
  return r;
}

std::vector<PoseRepeat> FindPoseRepeats(const std::vector<Capture>& captures, const SensorModel& rough) {
  std::vector<PoseRepeat> repeats;
  for (size_t j = 0; j < captures.size(); ++j) {
    const Capture& again = captures[j];
    if (again.kind != CaptureKind::kStatic || !again.used() || again.label.empty()) continue;
    for (size_t i = 0; i < j; ++i) {
      const Capture& first = captures[i];
      if (first.kind != CaptureKind::kStatic || !first.used() || first.label != again.label) continue;
      repeats.push_back(ComparePoseRepeat(first, again, rough));
      break;
    }
  }
  return repeats;
}

std::vector<std::string> RepeatedPoseLabels(const std::vector<PoseRepeat>& repeats) {
  std::vector<std::string> labels;
  for (const PoseRepeat& r : repeats)
    if (std::find(labels.begin(), labels.end(), r.label) == labels.end()) labels.push_back(r.label);
  return labels;
}

std::string DescribePoseRepeatPath(const std::vector<PoseRepeat>& repeats, const std::string& label) {
  std::vector<const PoseRepeat*> path;
  for (const PoseRepeat& r : repeats)
    if (r.label == label) path.push_back(&r);
  if (path.empty()) return "";
  if (path.size() == 1) return label + " taken again " + DescribePoseRepeat(*path.front());
  std::string moves;
  double noise2 = 0.0, largest = 0.0;
  bool beyond = false;
  for (const PoseRepeat* r : path) {
    const std::string elapsed = ElapsedWords(r->elapsed_s);
    moves += fmt::format("{}{:+.1f} counts{}{}", moves.empty() ? "" : ", ", r->moved_counts,
                         elapsed.empty() ? "" : " after ", elapsed);
    noise2 += r->noise_counts * r->noise_counts;
    largest = std::max(largest, std::abs(r->moved_counts));
    beyond = beyond || r->beyond_noise;
  }
  return fmt::format("{}, taken again {} times, moved along gravity since the first time: {} (noise of "
                     "each move about {:.1f} counts); at most {:.1f} counts, {}",
                     label, path.size(), moves, std::sqrt(noise2 / static_cast<double>(path.size())), largest,
                     beyond ? "more than noise explains" : "within noise");
}

std::string DescribePoseRepeat(const PoseRepeat& r) {
  const std::string elapsed = ElapsedWords(r.elapsed_s);
  return fmt::format("moved {:.1f} counts along gravity{}{}, {} its noise ({:.1f} counts){}", std::abs(r.moved_counts),
                     elapsed.empty() ? "" : " in ", elapsed, r.beyond_noise ? "more than" : "within",
                     r.noise_counts, r.beyond_noise ? " explains" : "");
}

std::string PoseRepeatLimitWords(const std::vector<PoseRepeat>& repeats, const std::string& label) {
  return fmt::format("limited by a pose that read differently when taken again: {} (a drift, a "
                     "sensor still warming, the prism or its mount moved); the uncertainty covers the "
                     "scatter between the captures", DescribePoseRepeatPath(repeats, label));
}

}  // namespace accelcal
