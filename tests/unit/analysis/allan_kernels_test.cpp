// The Allan deviation's inner loops (allan_kernels.h), on whichever path this processor takes
// (AVX2 or Eigen's SSE2 packets), against the sums written out term by term in long double:
// every length from 0 to 70 (the four-lane blocks and every tail), data of a realistic kind (a
// random walk: the readings' sum, less the first), and slices that start off 32-byte alignment.
#include "accelcal/analysis/allan_kernels.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace accelcal::detail {
namespace {

std::vector<double> RandomWalk(size_t n) {
  std::mt19937_64 rng(952);
  std::normal_distribution<double> reading(0.0, 3.0);
  std::vector<double> phase(n);
  double x = 0.0;
  for (double& p : phase) p = x += reading(rng);
  return phase;
}

void ExpectNear(double got, long double want, const char* what) {
  const double tolerance = 1e-13 * std::fabs(static_cast<double>(want)) + 1e-300;
  EXPECT_NEAR(got, static_cast<double>(want), tolerance) << what;
}

TEST(AllanKernels, SecondDifferencesEqualTheTermByTermSum) {
  const std::vector<double> phase = RandomWalk(400);
  for (size_t start : {size_t{0}, size_t{1}, size_t{3}}) {
    for (size_t m : {size_t{1}, size_t{5}, size_t{64}}) {
      for (size_t n = 0; n <= 70; ++n) {
        SCOPED_TRACE(testing::Message() << "start " << start << ", m " << m << ", n " << n);
        const double* x0 = phase.data() + start;
        long double want = 0;
        for (size_t i = 0; i < n; ++i) {
          const long double d = static_cast<long double>(x0[i + 2 * m]) - 2.0L * x0[i + m] + x0[i];
          want += d * d;
        }
        const double got = SumSquaredSecondDifferences(x0, x0 + m, x0 + 2 * m, n);
        ExpectNear(got, want, "sum of squares");
        if (n > 0) {
          EXPECT_GT(got, 0.0);
        }
      }
    }
  }
}

TEST(AllanKernels, LagOneSumsEqualTheTermByTermSums) {
  const std::vector<double> series = RandomWalk(200);
  for (size_t start : {size_t{0}, size_t{1}, size_t{3}}) {
    for (size_t k = 0; k <= 70; ++k) {
      SCOPED_TRACE(testing::Message() << "start " << start << ", k " << k);
      const double* s = series.data() + start;
      long double values = 0, squares = 0, earlier = 0, products = 0;
      for (size_t i = 1; i <= k; ++i) {
        values += s[i];
        squares += static_cast<long double>(s[i]) * s[i];
        earlier += s[i - 1];
        products += static_cast<long double>(s[i - 1]) * s[i];
      }
      const Lag1RunSums got = SumLag1Run(s, k);
      // Sums of signed values: held to the sum of their sizes, not to a sum that may cancel.
      long double sizes = 0;
      for (size_t i = 0; i <= k; ++i) sizes += std::fabs(s[i]);
      EXPECT_NEAR(got.values, static_cast<double>(values), 1e-14 * static_cast<double>(sizes) + 1e-300);
      EXPECT_NEAR(got.earlier, static_cast<double>(earlier), 1e-14 * static_cast<double>(sizes) + 1e-300);
      ExpectNear(got.squares, squares, "squares");
      long double product_sizes = 0;
      for (size_t i = 1; i <= k; ++i) product_sizes += std::fabs(s[i - 1] * s[i]);
      EXPECT_NEAR(got.products, static_cast<double>(products), 1e-14 * static_cast<double>(product_sizes) + 1e-300);
      if (k == 0) {
        EXPECT_EQ(got.values, 0.0);
        EXPECT_EQ(got.products, 0.0);
      }
    }
  }
}

}  // namespace
}  // namespace accelcal::detail
