#include "accelcal/acquire/window_sums.h"

#include <gtest/gtest.h>

namespace accelcal::detail {
namespace {

TEST(WindowSums, MeanVarianceAndSlopeOfALine) {
  WindowSums sums;
  sums.Reset({33000, 0, 0}, 5000.0);  // far from zero: the shifted origin keeps it exact
  for (int k = 0; k < 11; ++k) {
    const double t = 5000.0 + 0.1 * k;
    sums.Add({33000.0 + 2.0 * (t - 5000.0), k % 2 == 0 ? 1.0 : -1.0, 7.0}, t);
  }
  EXPECT_EQ(sums.n(), 11);
  EXPECT_NEAR(sums.Mean().x(), 33001.0, 1e-9);
  EXPECT_NEAR(sums.SlopePerS().x(), 2.0, 1e-9);
  EXPECT_NEAR(sums.SlopePerS().z(), 0.0, 1e-12);
  EXPECT_NEAR(sums.Variance().z(), 0.0, 1e-12);
  EXPECT_NEAR(sums.Variance().y(), 11.0 / 10.0 - 1.0 / 110.0, 1e-9);  // +-1 alternating, 6 vs 5
}

TEST(WindowSums, RemoveUndoesAdd) {
  WindowSums sums;
  sums.Reset({0, 0, 0}, 0.0);
  sums.Add({1, 2, 3}, 0.0);
  sums.Add({3, 2, 1}, 1.0);
  sums.Add({9, 9, 9}, 2.0);
  sums.Remove({9, 9, 9}, 2.0);
  EXPECT_EQ(sums.n(), 2);
  EXPECT_NEAR(sums.Mean().x(), 2.0, 1e-12);
  EXPECT_NEAR(sums.SlopePerS().z(), -2.0, 1e-12);
  sums.Remove({3, 2, 1}, 1.0);
  EXPECT_TRUE(std::isnan(sums.Variance().x()));
  EXPECT_TRUE(std::isnan(sums.SlopePerS().x()));
}

}  // namespace
}  // namespace accelcal::detail
