#include "accelcal/acquire/detail/sliding_variance.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace accelcal::detail {
namespace {

// Two-pass variance of the window centred at `centre`.
Eigen::Vector3d BruteForce(const std::vector<Sample>& s, long centre, long h) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (long k = centre - h; k <= centre + h; ++k) mean += s[static_cast<size_t>(k)].raw_counts;
  mean /= static_cast<double>(2 * h + 1);
  Eigen::Vector3d sum_sq = Eigen::Vector3d::Zero();
  for (long k = centre - h; k <= centre + h; ++k) {
    sum_sq += (s[static_cast<size_t>(k)].raw_counts - mean).cwiseAbs2();
  }
  return sum_sq / static_cast<double>(2 * h);
}

TEST(SlidingWindowVariance, MatchesTwoPassOnLargeOffsetsAcrossResyncs) {
  // A large offset and a slow drift against a small spread: the case where naive running sums
  // of x^2 lose every significant digit. 10000 samples cross the periodic recomputation.
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<Sample> s(10000);
  for (size_t i = 0; i < s.size(); ++i) {
    const double drift = 1e7 + 0.5 * static_cast<double>(i);
    s[i].raw_counts = {drift + noise(rng), -drift + noise(rng), 1e9 + noise(rng)};
  }
  const int window = 101;
  const std::vector<Eigen::Vector3d> v = SlidingWindowVariance(s, window);
  ASSERT_EQ(v.size(), s.size());
  EXPECT_TRUE(std::isnan(v[49].x()));
  EXPECT_TRUE(std::isnan(v[s.size() - 50].x()));
  for (long i = 50; i < static_cast<long>(s.size()) - 50; i += 37) {
    const Eigen::Vector3d expected = BruteForce(s, i, 50);
    EXPECT_LT((v[static_cast<size_t>(i)] - expected).cwiseAbs().maxCoeff(),
              1e-6 * expected.maxCoeff()) << "at " << i;
  }
}

TEST(SlidingWindowVariance, TooShortGivesOnlyNaN) {
  std::vector<Sample> s(5);
  for (const Eigen::Vector3d& v : SlidingWindowVariance(s, 7)) EXPECT_TRUE(std::isnan(v.x()));
}

}  // namespace
}  // namespace accelcal::detail
