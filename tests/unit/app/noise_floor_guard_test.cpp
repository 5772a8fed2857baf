// The wizard's noise floor kept honest: refused when measured on a shaking bench, lowered when
// a still capture proves it too high, and the captures judged with it judged again. Samples
// are drawn here from plain Gaussian noise (no project code in the generator).
#include "accelcal/app/wizard/noise_floor_guard.h"

#include <random>

#include <gtest/gtest.h>

#include "test_support.h"

namespace accelcal::noise_floor_guard_test {
namespace {

using testing::Contains;

std::vector<Sample> Noise(double std_counts, double seconds, std::uint64_t seed, double t0_s = 0.0) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, std_counts);
  std::vector<Sample> out;
  for (int k = 0; k < static_cast<int>(seconds * 100); ++k) {
    Sample s;
    s.t_s = t0_s + k * 0.01;
    s.raw_counts = Eigen::Vector3d(2048 + n(rng), 2048 + n(rng), 2390 + n(rng));
    out.push_back(s);
  }
  return out;
}

Capture Static(int id, double std_counts, std::uint64_t seed) {
  Capture c;
  c.id = id;
  c.label = "pose " + std::to_string(id);
  c.samples = Noise(std_counts, 10.0, seed, 100.0 * id);
  return c;
}

NoiseFloorGuard Guard(double expected_counts) {
  return NoiseFloorGuard(Eigen::Vector3d::Constant(expected_counts), 2.0, StaticStabilityOptions{});
}

TEST(NoiseFloorGuard, AStillQuietPeriodGivesTheFloor) {
  NoiseFloorGuard g = Guard(1.6);
  const NoiseFloorJudgement j = g.Judge(Noise(1.5, 2.0, 1));
  EXPECT_TRUE(j.ok) << j.reason;
  ASSERT_TRUE(g.floor().has_value());
  EXPECT_NEAR(g.floor()->std_counts.x(), 1.5, 0.2);
  EXPECT_TRUE(Contains(g.Describe(), "quiet period"));
}

// Issue 12, problem 3: a floor measured while the bench shook let every shaking capture pass.
TEST(NoiseFloorGuard, AFloorFarAboveTheExpectedNoiseIsRefusedWithTheReason) {
  NoiseFloorGuard g = Guard(1.6);
  const NoiseFloorJudgement j = g.Judge(Noise(7.5, 2.0, 2));
  EXPECT_FALSE(j.ok);
  EXPECT_FALSE(g.floor().has_value());
  EXPECT_TRUE(Contains(j.reason, "the sensor was not still while the noise floor was measured")) << j.reason;
  EXPECT_TRUE(Contains(j.reason, "over 2 x the")) << j.reason;
}

TEST(NoiseFloorGuard, ADriftingQuietPeriodIsRefusedEvenWithoutAnExpectation) {
  NoiseFloorGuard g(Eigen::Vector3d::Constant(kNaN), 2.0, StaticStabilityOptions{});
  std::vector<Sample> quiet = Noise(1.5, 2.0, 3);
  for (size_t k = 0; k < quiet.size(); ++k) quiet[k].raw_counts.x() += 0.05 * static_cast<double>(k);
  const NoiseFloorJudgement j = g.Judge(quiet);
  EXPECT_FALSE(j.ok);
  EXPECT_TRUE(Contains(j.reason, "drifting")) << j.reason;
}

TEST(NoiseFloorGuard, AStillCaptureLowersATooHighFloorAndTheShakingOnesFailAgain) {
  NoiseFloorGuard g(Eigen::Vector3d::Constant(kNaN), 2.0, StaticStabilityOptions{});
  ASSERT_TRUE(g.Judge(Noise(7.5, 2.0, 4)).ok);  // no expectation: the shaking floor passes
  const Capture shaking1 = Static(1, 7.5, 5), shaking2 = Static(2, 7.0, 6);
  const Capture still = Static(3, 1.5, 7);
  // A shaking capture does not lower it.
  EXPECT_FALSE(g.Recheck(shaking1, {&shaking1}).lowered);
  const NoiseFloorRecheck r = g.Recheck(still, {&shaking1, &shaking2, &still});
  ASSERT_TRUE(r.lowered);
  EXPECT_NEAR(g.floor()->std_counts.x(), 1.5, 0.1);
  EXPECT_TRUE(Contains(r.note, "the noise floor proved too high")) << r.note;
  ASSERT_EQ(r.failing.size(), 2u);
  EXPECT_EQ(r.failing[0].capture_id, 1);
  EXPECT_EQ(r.failing[1].capture_id, 2);
  EXPECT_TRUE(Contains(r.failing[0].reason, "not still: moving")) << r.failing[0].reason;
  // A second still capture does not lower it again.
  const Capture still2 = Static(4, 1.5, 8);
  EXPECT_FALSE(g.Recheck(still2, {&still, &still2}).lowered);
}

}  // namespace
}  // namespace accelcal::noise_floor_guard_test
