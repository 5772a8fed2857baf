// The statistics a capture carries: what each field holds, and that they are computed once.
#include "accelcal/base/capture.h"

#include <gtest/gtest.h>

namespace accelcal {
namespace {

Sample At(double t, double x) {
  Sample s;
  s.t_s = t;
  s.raw_counts = Eigen::Vector3d(x, 2.0 * x, 0.0);
  return s;
}

TEST(CaptureStats, TheCoMomentIsTheSumOfSquaredDeviationsAndTheCovarianceDividesIt) {
  // Readings -1, 1, -1, 1: mean 0, sum of squared deviations 4, sample variance 4/3.
  const CaptureStats s = ComputeStats({At(0, -1), At(1, 1), At(2, -1), At(3, 1)});
  EXPECT_DOUBLE_EQ(s.comoment_counts2(0, 0), 4.0);
  EXPECT_DOUBLE_EQ(s.comoment_counts2(0, 1), 8.0);
  EXPECT_DOUBLE_EQ(s.Covariance()(0, 0), 4.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.Covariance()(1, 1), 16.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.MeanCovariance()(0, 0), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.StdCounts()(0), std::sqrt(4.0 / 3.0));
}

TEST(CaptureStats, ACaptureCarriesTheStatisticsItWasGivenAndRecomputesWhenSamplesAreAdded) {
  Capture c;
  c.samples = {At(0, -1), At(1, 1)};
  // Handed over by the capture engine: kept as given (here deliberately not what the samples
  // give, to see that nothing recomputes them behind the caller's back).
  CaptureStats given = ComputeStats(c.samples);
  given.mean_t_s = 42.0;
  c.set_stats(given);
  EXPECT_EQ(c.stats().mean_t_s, 42.0);
  const Capture copy = c;
  EXPECT_EQ(copy.stats().mean_t_s, 42.0);
  // A sample appended: the statistics follow the samples again.
  c.samples.push_back(At(2, 3));
  EXPECT_EQ(c.stats().n, 3);
  EXPECT_DOUBLE_EQ(c.stats().mean_t_s, 1.0);
  EXPECT_DOUBLE_EQ(c.stats().mean_counts.x(), 1.0);
}

TEST(CaptureStats, ACaptureWithoutGivenStatisticsComputesThemOnFirstUse) {
  Capture c;
  c.samples = {At(0, 2), At(1, 4)};
  EXPECT_EQ(c.stats().n, 2);
  EXPECT_DOUBLE_EQ(c.stats().mean_counts.x(), 3.0);
}

}  // namespace
}  // namespace accelcal
