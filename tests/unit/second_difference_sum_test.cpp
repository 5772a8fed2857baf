// The Allan deviation's inner sum (second_difference_sum.h), on whichever path this processor
// takes (AVX2 or Eigen's SSE2 packets), against the sum written out term by term in long
// double: every length from 0 to 70 (the four-lane blocks and every tail), phases of a
// realistic kind (a random walk: the readings' sum, less the first), and a slice that starts off 32-byte alignment.
#include "accelcal/analysis/second_difference_sum.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace accelcal::detail {
namespace {

long double Reference(const double* x0, const double* x1, const double* x2, size_t n) {
  long double sum = 0;
  for (size_t i = 0; i < n; ++i) {
    const long double d = static_cast<long double>(x2[i]) - 2.0L * x1[i] + x0[i];
    sum += d * d;
  }
  return sum;
}

TEST(SecondDifferenceSum, EqualsTheTermByTermSumForEveryLengthAndOffset) {
  std::mt19937_64 rng(952);
  std::normal_distribution<double> reading(0.0, 3.0);
  std::vector<double> phase(400);
  double x = 0.0;
  for (double& p : phase) p = x += reading(rng);  // the phase of readings less their first
  for (size_t start : {size_t{0}, size_t{1}, size_t{3}}) {
    for (size_t m : {size_t{1}, size_t{5}, size_t{64}}) {
      for (size_t n = 0; n <= 70; ++n) {
        const double* x0 = phase.data() + start;
        const double got = SumSquaredSecondDifferences(x0, x0 + m, x0 + 2 * m, n);
        const long double want = Reference(x0, x0 + m, x0 + 2 * m, n);
        ASSERT_NEAR(got, static_cast<double>(want), 1e-13 * static_cast<double>(want) + 1e-300)
            << "start " << start << ", m " << m << ", n " << n;
        if (n > 0) {
          ASSERT_GT(got, 0.0);
        }
      }
    }
  }
}

}  // namespace
}  // namespace accelcal::detail
