#include "accelcal/detail/sliding_variance.h"

namespace accelcal::detail {
namespace {

// Steps between exact recomputations of the running sums.
constexpr long kResyncSteps = 4096;

// Sums of (x - origin) and (x - origin)^2 over a window.
struct ShiftedSums {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_sq = Eigen::Vector3d::Zero();

  void Add(const Eigen::Vector3d& x) {
    const Eigen::Vector3d d = x - origin;
    sum += d;
    sum_sq += d.cwiseProduct(d);
  }
  void Remove(const Eigen::Vector3d& x) {
    const Eigen::Vector3d d = x - origin;
    sum -= d;
    sum_sq -= d.cwiseProduct(d);
  }
  Eigen::Vector3d Variance(long n) const {
    const double nd = static_cast<double>(n);
    const Eigen::Vector3d ss = sum_sq - sum.cwiseProduct(sum) / nd;
    return (ss / (nd - 1.0)).cwiseMax(0.0);  // rounding may leave a tiny negative
  }
};

ShiftedSums SumsFromScratch(const std::vector<Sample>& samples, long first, long count) {
  ShiftedSums sums;
  sums.origin = samples[static_cast<size_t>(first)].raw_counts;
  for (long k = first; k < first + count; ++k) sums.Add(samples[static_cast<size_t>(k)].raw_counts);
  return sums;
}

}  // namespace

std::vector<Eigen::Vector3d> SlidingWindowVariance(const std::vector<Sample>& samples,
                                                   int window_samples) {
  const long n = static_cast<long>(samples.size());
  const long w = window_samples;
  const long h = w / 2;
  std::vector<Eigen::Vector3d> variance(samples.size(), Eigen::Vector3d::Constant(kNaN));
  if (n < w) return variance;

  ShiftedSums sums = SumsFromScratch(samples, 0, w);
  for (long centre = h;; ++centre) {
    variance[static_cast<size_t>(centre)] = sums.Variance(w);
    const long leaving = centre - h;
    const long entering = centre + h + 1;
    if (entering >= n) break;
    if ((leaving + 1) % kResyncSteps == 0) {
      sums = SumsFromScratch(samples, leaving + 1, w);
    } else {
      sums.Remove(samples[static_cast<size_t>(leaving)].raw_counts);
      sums.Add(samples[static_cast<size_t>(entering)].raw_counts);
    }
  }
  return variance;
}

}  // namespace accelcal::detail
