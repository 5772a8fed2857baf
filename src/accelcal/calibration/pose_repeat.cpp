#include "accelcal/calibration/pose_repeat.h"

#include <cmath>

#include <fmt/core.h>

namespace accelcal {
namespace {

// Chi-square's 0.999 quantile at 3 degrees of freedom.
constexpr double kChi2Limit3Dof = 16.27;

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

PoseRepeat ComparePoseRepeat(const Capture& first, const Capture& again) {
  PoseRepeat r;
  r.label = again.label;
  r.first_id = first.id;
  r.again_id = again.id;
  r.elapsed_s = again.stats().mean_t_s - first.stats().mean_t_s;
  Eigen::Vector3d m1, s1, m2, s2;
  ReadingOf(first, m1, s1);
  ReadingOf(again, m2, s2);
  r.moved_counts = m2 - m1;
  r.noise_counts = (s1.array().square() + s2.array().square()).sqrt().matrix();
  for (int i = 0; i < 3; ++i)
    if (r.noise_counts(i) > 0.0) r.chi2 += std::pow(r.moved_counts(i) / r.noise_counts(i), 2);
  r.beyond_noise = r.chi2 > kChi2Limit3Dof;
  return r;
}

std::vector<PoseRepeat> FindPoseRepeats(const std::vector<Capture>& captures) {
  std::vector<PoseRepeat> repeats;
  for (size_t j = 0; j < captures.size(); ++j) {
    const Capture& again = captures[j];
    if (again.kind != CaptureKind::kStatic || !again.used() || again.label.empty()) continue;
    const Capture* first = nullptr;
    const Capture* later = nullptr;  // a capture of the pose after this one: that one reports
    for (size_t i = 0; i < captures.size(); ++i) {
      const Capture& c = captures[i];
      if (i == j || c.kind != CaptureKind::kStatic || !c.used() || c.label != again.label) continue;
      if (i < j && first == nullptr) first = &c;
      if (i > j) later = &c;
    }
    if (first != nullptr && later == nullptr) repeats.push_back(ComparePoseRepeat(*first, again));
  }
  return repeats;
}

std::string DescribePoseRepeat(const PoseRepeat& r) {
  Eigen::Index axis = 0;
  r.moved_counts.cwiseAbs().maxCoeff(&axis);
  const std::string elapsed = ElapsedWords(r.elapsed_s);
  return fmt::format("moved {:.1f} counts{}{}, {} its noise ({:.1f} counts){}",
                     std::abs(r.moved_counts(axis)), elapsed.empty() ? "" : " in ", elapsed,
                     r.beyond_noise ? "more than" : "within", r.noise_counts(axis),
                     r.beyond_noise ? " explains" : "");
}

std::string PoseRepeatLimitWords(const PoseRepeat& r) {
  return fmt::format("limited by a pose that read differently when taken again: {} {} (a drift, a "
                     "sensor still warming, the prism or its mount moved); the uncertainty covers the "
                     "scatter between the captures", r.label, DescribePoseRepeat(r));
}

}  // namespace accelcal
