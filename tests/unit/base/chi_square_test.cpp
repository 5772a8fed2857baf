#include "accelcal/base/chi_square.h"

#include <cmath>

#include <gtest/gtest.h>

namespace accelcal {
namespace {

// Closed forms: dof 2 -> exp(-x/2); dof 1 -> erfc(sqrt(x/2)); dof 4 -> exp(-x/2)(1 + x/2).
TEST(ChiSquare, MatchesClosedForms) {
  for (double x : {0.01, 0.5, 1.0, 3.0, 9.0, 25.0, 80.0}) {
    EXPECT_NEAR(ChiSquareSurvival(x, 2), std::exp(-x / 2), 1e-13 + 1e-11 * std::exp(-x / 2)) << x;
    EXPECT_NEAR(ChiSquareSurvival(x, 1), std::erfc(std::sqrt(x / 2)), 1e-12) << x;
    EXPECT_NEAR(ChiSquareSurvival(x, 4), std::exp(-x / 2) * (1 + x / 2), 1e-12) << x;
  }
}

// Textbook critical values: P = 0.05 at 16.919 for 9 dof, 0.01 at 21.666; 0.05 at 43.773 for 30.
TEST(ChiSquare, MatchesTableCriticalValues) {
  EXPECT_NEAR(ChiSquareSurvival(16.919, 9), 0.05, 1e-4);
  EXPECT_NEAR(ChiSquareSurvival(21.666, 9), 0.01, 1e-4);
  EXPECT_NEAR(ChiSquareSurvival(43.773, 30), 0.05, 1e-4);
}

TEST(ChiSquare, RejectsNonsense) {
  EXPECT_TRUE(std::isnan(ChiSquareSurvival(1.0, 0)));
  EXPECT_TRUE(std::isnan(ChiSquareSurvival(-1.0, 3)));
  EXPECT_EQ(ChiSquareSurvival(0.0, 3), 1.0);
}

// Closed form for 2 dof: chi2 = -2 ln(1 - p); printed table values (5 significant digits) for
// others; the quantile inverts the CDF for non-integer dof (equivalent degrees of freedom).
TEST(ChiSquare, QuantileMatchesClosedFormAndTables) {
  for (double p : {0.001, 0.1587, 0.5, 0.8413, 0.999}) {
    EXPECT_NEAR(ChiSquareQuantile(p, 2.0), -2.0 * std::log1p(-p), 1e-12 * (1 - 2.0 * std::log1p(-p)))
        << p;
  }
  EXPECT_NEAR(ChiSquareQuantile(0.95, 10.0), 18.307, 5e-4);
  EXPECT_NEAR(ChiSquareQuantile(0.05, 10.0), 3.9403, 5e-5);
  EXPECT_NEAR(ChiSquareQuantile(0.975, 1.0), 5.0239, 5e-5);
  EXPECT_NEAR(ChiSquareQuantile(0.01, 30.0), 14.953, 5e-4);
  EXPECT_NEAR(ChiSquareQuantile(0.99, 100.0), 135.807, 5e-4);
  for (double dof : {0.7, 3.3, 47.25, 1234.5, 1.9e5}) {
    for (double p : {0.02, 0.1587, 0.8413, 0.98}) {
      // The CDF's own rounding grows with dof (sums of ~sqrt(dof) terms).
      EXPECT_NEAR(ChiSquareCdf(ChiSquareQuantile(p, dof), dof), p, dof < 1e4 ? 1e-12 : 1e-10)
          << dof << " " << p;
    }
  }
  // Beyond 2e5 dof: Wilson-Hilferty, checked with the exact CDF.
  for (double p : {0.1587, 0.8413}) {
    EXPECT_NEAR(ChiSquareCdf(ChiSquareQuantile(p, 2.1e5), 2.1e5), p, 1e-6) << p;
  }
}

TEST(ChiSquare, QuantileRejectsNonsense) {
  EXPECT_TRUE(std::isnan(ChiSquareQuantile(0.0, 3.0)));
  EXPECT_TRUE(std::isnan(ChiSquareQuantile(1.0, 3.0)));
  EXPECT_TRUE(std::isnan(ChiSquareQuantile(0.5, 0.0)));
  EXPECT_TRUE(std::isnan(ChiSquareQuantile(std::nan(""), 3.0)));
  EXPECT_TRUE(std::isnan(ChiSquareCdf(1.0, -1.0)));
}

}  // namespace
}  // namespace accelcal
