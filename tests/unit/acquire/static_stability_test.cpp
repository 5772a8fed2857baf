#include "accelcal/acquire/capture_engine/static_stability.h"

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "capture_engine_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

using testing::Contains;

const NoiseFloor kDefaultFloor = NoiseFloor::Given({1.5, 1.5, 1.7});  // the default sensor's

TEST(StaticStability, CleanWindowsPassAtALowFalseAlarmRate) {
  // 5 s quiet period for the floor, then 200 windows of 2 s of the same still pose.
  const std::vector<Sample> samples =
      testing::FirstCaptureSamples(testing::OnePose({0, 0, 1}, 405.0));
  const std::vector<Sample> quiet(samples.begin(), samples.begin() + 500);
  const NoiseFloor floor = NoiseFloor::FromQuietPeriod(ComputeStats(quiet));
  ASSERT_EQ(floor.Validate(), "");
  int unstable = 0;
  for (int w = 0; w < 200; ++w) {
    const auto first = samples.begin() + 500 + 200 * w;
    const StabilityVerdict v =
        EvaluateStaticStability({first, first + 200}, floor, StaticStabilityOptions{});
    ASSERT_TRUE(v.judged);
    if (!v.stable) ++unstable;
    EXPECT_LT(v.WorstRatio(), 1.5) << v.reason;
  }
  EXPECT_LE(unstable, 1);
}

TEST(StaticStability, BumpIsASpikeInWords) {
  sim::Scenario scenario = testing::OnePose({0, 0, 1}, 10.0);
  scenario.effects.bumps.push_back({0, 4.0, 2.0, 0.1});
  const StabilityVerdict v = EvaluateStaticStability(testing::FirstCaptureSamples(scenario),
                                                     kDefaultFloor, StaticStabilityOptions{});
  ASSERT_TRUE(v.judged);
  EXPECT_FALSE(v.stable);
  EXPECT_TRUE(Contains(v.reason, "spike: ")) << v.reason;
  EXPECT_TRUE(Contains(v.reason, "sigma) at t = 4.")) << v.reason;
  ASSERT_TRUE(v.largest_spike.has_value());
  EXPECT_GT(v.WorstRatio(), 1.0);
}

TEST(StaticStability, SlowDriftIsDrifting) {
  sim::Scenario scenario = testing::OnePose({0, 0, 1}, 10.0);
  scenario.effects.bias_drift_counts_per_s = {0.0, 0.0, 0.6};  // 6 counts over the capture
  const StabilityVerdict v = EvaluateStaticStability(testing::FirstCaptureSamples(scenario),
                                                     kDefaultFloor, StaticStabilityOptions{});
  EXPECT_FALSE(v.stable);
  EXPECT_TRUE(Contains(v.reason, "drifting: z moved ")) << v.reason;
  EXPECT_TRUE(Contains(v.reason, "counts over the window, limit 3.4")) << v.reason;
  EXPECT_NEAR(v.trend_counts.z(), 6.0, 0.5);
  EXPECT_FALSE(Contains(v.reason, "moving")) << v.reason;
}

TEST(StaticStability, HandOnTheTableIsMoving) {
  const SensorModel model = sim::DefaultScenario().sensor.model;
  testing::SyntheticStream stream(model, 1.5);
  const StabilityVerdict v = EvaluateStaticStability(stream.Pose({0, 0, 1}, 5.0, 4.0),
                                                     kDefaultFloor, StaticStabilityOptions{});
  EXPECT_FALSE(v.stable);
  EXPECT_TRUE(Contains(v.reason, "moving: x std 3.")) << v.reason;
  EXPECT_TRUE(Contains(v.reason, "counts, limit 2.2")) << v.reason;
  EXPECT_GT(v.StdRatio().x(), 1.0);
  EXPECT_LT(v.StdRatio().y(), 1.2);
}

TEST(StaticStability, TooFewSamplesAreNotJudged) {
  const SensorModel model = sim::DefaultScenario().sensor.model;
  testing::SyntheticStream stream(model, 1.5);
  const StabilityVerdict v = EvaluateStaticStability(stream.Pose({0, 0, 1}, 0.2), kDefaultFloor,
                                                     StaticStabilityOptions{});
  EXPECT_FALSE(v.judged);
  EXPECT_FALSE(v.stable);
  EXPECT_EQ(v.reason, "judging: 20 of 50 samples");
  EXPECT_TRUE(std::isnan(v.WorstRatio()));
}

TEST(StaticStability, SlidingWindowForgetsABumpOnceItHasPassed) {
  sim::Scenario scenario = testing::OnePose({0, 0, 1}, 10.0);
  scenario.effects.bumps.push_back({0, 2.0, 2.0, 0.1});
  StaticStabilityMonitor monitor(StaticStabilityOptions{}, kDefaultFloor, 2.0);
  bool was_unstable = false;
  for (const Sample& s : testing::FirstCaptureSamples(scenario)) {
    monitor.Add(s);
    if (s.t_s > 2.2 && s.t_s < 3.0) was_unstable |= !monitor.Verdict().stable;
  }
  EXPECT_TRUE(was_unstable);
  EXPECT_TRUE(monitor.full());
  EXPECT_TRUE(monitor.Verdict().stable) << monitor.Verdict().reason;
  EXPECT_LE(monitor.n(), 201);
}

TEST(StaticStability, OptionsAndFloorAreValidated) {
  StaticStabilityOptions bad;
  bad.std_multiplier = 1.0;
  EXPECT_TRUE(Contains(bad.Validate(), "std_multiplier"));
  EXPECT_THROW(EvaluateStaticStability({}, kDefaultFloor, bad), Error);
  EXPECT_THROW(EvaluateStaticStability({}, NoiseFloor{}, StaticStabilityOptions{}), Error);
  EXPECT_EQ(StaticStabilityOptions{}.Validate(), "");
}

}  // namespace
}  // namespace accelcal
