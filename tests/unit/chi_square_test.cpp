#include "accelcal/diagnosis/chi_square.h"

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

}  // namespace
}  // namespace accelcal
