#include "accelcal/acquire/detail/sliding_variance.h"

#include "accelcal/acquire/window_sums.h"

namespace accelcal::detail {
namespace {

// Steps between exact recomputations of the running sums.
constexpr long kResyncSteps = 4096;

// The sums of samples [first, first + count), measured from the first one.
WindowSums SumsFromScratch(const std::vector<Sample>& samples, long first, long count) {
  WindowSums sums;
  const Sample& origin = samples[static_cast<size_t>(first)];
  sums.Reset(origin.raw_counts, origin.t_s);
  for (long k = first; k < first + count; ++k) {
    const Sample& s = samples[static_cast<size_t>(k)];
    sums.Add(s.raw_counts, s.t_s);
  }
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

  WindowSums sums = SumsFromScratch(samples, 0, w);
  for (long centre = h;; ++centre) {
    variance[static_cast<size_t>(centre)] = sums.Variance();
    const long leaving = centre - h;
    const long entering = centre + h + 1;
    if (entering >= n) break;
    if ((leaving + 1) % kResyncSteps == 0) {
      sums = SumsFromScratch(samples, leaving + 1, w);
    } else {
      const Sample& out = samples[static_cast<size_t>(leaving)];
      const Sample& in = samples[static_cast<size_t>(entering)];
      sums.Remove(out.raw_counts, out.t_s);
      sums.Add(in.raw_counts, in.t_s);
    }
  }
  return variance;
}

}  // namespace accelcal::detail
