#include "accelcal/acquire/capture_engine/turntable_stability.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "accelcal/acquire/sim/virtual_bench.h"
#include "test_support.h"

namespace accelcal::turntable_stability_test {
namespace {

using testing::Contains;

// One turntable run of the default bench: +x radial, z up, 0.10 m at 120 rpm, 10 s.
sim::Scenario OneRun(double tilt_rad = 0.0) {
  sim::Scenario s = sim::DefaultScenario();
  s.captures = {s.captures[10]};
  s.effects.turntable_tilt_rad = tilt_rad;
  return s;
}

std::vector<Sample> RunSamples(const sim::Scenario& s) {
  sim::VirtualBench bench(s);
  return bench.SimulateCaptureSet().front().samples;
}

TurntableSetup Entered(double radius_m, double rpm) {
  TurntableSetup setup;
  setup.radius_m = radius_m;
  setup.rpm = rpm;
  return setup;
}

const SensorModel kModel = sim::DefaultScenario().sensor.model;

TEST(TurntableStability, MatchingRunPasses) {
  const sim::Scenario s = OneRun();
  ASSERT_DOUBLE_EQ(s.captures[0].radius_m, 0.10);
  const TurntableVerdict v =
      EvaluateTurntable(RunSamples(s), kModel, Entered(0.10, 120), TurntableStabilityOptions{});
  EXPECT_TRUE(v.ok) << v.reason;
  EXPECT_NEAR(v.centripetal_ratio, 1.0, 0.02);
  EXPECT_NEAR(v.expected_centripetal_mps2, 15.79, 0.01);
  EXPECT_EQ(v.sub_window_centripetal_mps2.size(), 4u);
  EXPECT_LT(v.speed_spread_fraction, 0.01);
}

TEST(TurntableStability, RadiusInCentimetresIsCaught) {
  const TurntableVerdict v =
      EvaluateTurntable(RunSamples(OneRun()), kModel, Entered(10.0, 120),
                        TurntableStabilityOptions{});
  EXPECT_FALSE(v.ok);
  EXPECT_FALSE(v.consistent);
  EXPECT_EQ(v.reason, "radius looks 100x too large: 10 m entered; did you mean 0.1 m?");
}

TEST(TurntableStability, RadiusInKilometresIsCaught) {
  const TurntableVerdict v = EvaluateTurntable(RunSamples(OneRun()), kModel, Entered(1e-4, 120),
                                               TurntableStabilityOptions{});
  EXPECT_EQ(v.reason, "radius looks 1000x too small: 0.0001 m entered; did you mean 0.1 m?");
}

TEST(TurntableStability, WrongRpmIsCaught) {
  const TurntableVerdict v =
      EvaluateTurntable(RunSamples(OneRun()), kModel, Entered(0.10, 60),
                        TurntableStabilityOptions{});
  EXPECT_FALSE(v.consistent);
  EXPECT_TRUE(Contains(v.reason, "centripetal 3.95 m/s^2 expected from 60 rpm at 0.1 m, 15."))
      << v.reason;
  EXPECT_TRUE(Contains(v.reason, "measured: check rpm and radius (the measurement fits 1"))
      << v.reason;
  EXPECT_NEAR(60.0 * std::sqrt(v.centripetal_ratio), 120.0, 2.0);
}

TEST(TurntableStability, TiltWobbleIsMeasuredAndTolerated) {
  const double tilt_rad = 0.02;  // 1.15 deg
  const TurntableVerdict v = EvaluateTurntable(RunSamples(OneRun(tilt_rad)), kModel,
                                               Entered(0.10, 120), TurntableStabilityOptions{});
  EXPECT_TRUE(v.ok) << v.reason;
  const double truth_mps2 = 9.80665 * std::sin(tilt_rad);
  EXPECT_NEAR(v.wobble_amplitude_mps2, truth_mps2, 0.2 * truth_mps2);
  EXPECT_NEAR(v.tilt_deg, tilt_rad * 180 / M_PI, 0.2 * tilt_rad * 180 / M_PI);
}

TEST(TurntableStability, StrongTiltIsRefused) {
  const TurntableVerdict v = EvaluateTurntable(RunSamples(OneRun(0.06)), kModel,
                                               Entered(0.10, 120), TurntableStabilityOptions{});
  EXPECT_FALSE(v.level);
  EXPECT_TRUE(v.steady);
  EXPECT_TRUE(Contains(v.reason, "the turntable is tilted 3.")) << v.reason;
  EXPECT_TRUE(Contains(v.reason, "tolerance 2 deg: level the turntable")) << v.reason;
}

// Issue 12, problem 2: at "+x radial, +z up" a sensor mounted +y radial was accepted.
TEST(TurntableStability, AWrongMountingIsRefusedNamingTheRadialAxis) {
  sim::Scenario s = OneRun();
  s.captures[0].radial_axis = sim::SensorAxis::kPlusY;  // the truth: +y outward
  const TurntableVerdict v =
      EvaluateTurntable(RunSamples(s), kModel, Entered(0.10, 120), TurntableStabilityOptions{});
  EXPECT_FALSE(v.ok);
  EXPECT_FALSE(v.mounted_as_asked);
  EXPECT_TRUE(v.steady);  // steady but wrong: the capture engine rejects it
  EXPECT_EQ(v.mounting_found, "+y radial, +z up");
  EXPECT_TRUE(Contains(v.reason, "wrong mounting: the samples show +y radial, +z up (the "
                                 "centripetal 15.")) << v.reason;
  EXPECT_TRUE(Contains(v.reason, "is on y), not +x radial, +z up: mount the sensor with +x "
                                 "pointing away from the spin axis and +z up")) << v.reason;
  // Upside down, and turned inward.
  s.captures[0].radial_axis = sim::SensorAxis::kPlusX;
  s.captures[0].up_axis = sim::SensorAxis::kMinusZ;
  EXPECT_EQ(EvaluateTurntable(RunSamples(s), kModel, Entered(0.10, 120), {}).mounting_found, "+x radial, -z up");
  s.captures[0].radial_axis = sim::SensorAxis::kMinusX;
  s.captures[0].up_axis = sim::SensorAxis::kPlusZ;
  EXPECT_EQ(EvaluateTurntable(RunSamples(s), kModel, Entered(0.10, 120), {}).mounting_found, "-x radial, +z up");
}

TEST(TurntableStability, ARightMountingPassesWhateverTheEnteredRadius) {
  // The mounting check fits the centripetal load itself: a radius typo is the radius check's.
  const TurntableVerdict v =
      EvaluateTurntable(RunSamples(OneRun()), kModel, Entered(0.05, 120), TurntableStabilityOptions{});
  EXPECT_TRUE(v.mounted_as_asked);
  EXPECT_FALSE(v.consistent);
  EXPECT_TRUE(Contains(v.reason, "m at 120 rpm)")) << v.reason;
}

// Issue 13, item 3: the once-per-revolution swing of a tilted table is fitted, its tilt
// reported, and removed from the samples: what is left is the sensor's own noise.
TEST(TurntableStability, TheSwingIsFittedAndRemovedLeavingTheSensorsNoise) {
  const double tilt_rad = 2.0 * M_PI / 180.0;
  std::vector<Sample> samples = RunSamples(OneRun(tilt_rad));
  TurntableStabilityOptions o;
  o.max_tilt_deg = 3.0;
  const TurntableVerdict v = EvaluateTurntable(samples, kModel, Entered(0.10, 120), o);
  ASSERT_TRUE(v.ok) << v.reason;
  EXPECT_NEAR(v.tilt_deg, 2.0, 0.1);
  const Eigen::Vector3d before = ComputeStats(samples).StdCounts();
  const Eigen::Vector3d mean_before = ComputeStats(samples).mean_counts;
  RemoveOncePerRevolution(&samples, v.swing);
  const Eigen::Vector3d after = ComputeStats(samples).StdCounts();
  const Eigen::Vector3d noise = sim::DefaultScenario().sensor.noise_counts;
  // Gravity's horizontal part (0.34 m/s^2, ~12 counts) swings on x and y; z does not move.
  EXPECT_GT(before.x(), 4.0 * noise.x());
  EXPECT_NEAR(after.x(), noise.x(), 0.15 * noise.x());
  EXPECT_NEAR(after.y(), noise.y(), 0.15 * noise.y());
  EXPECT_NEAR(after.z(), noise.z(), 0.15 * noise.z());
  // Whole revolutions: the mean stays.
  EXPECT_NEAR((ComputeStats(samples).mean_counts - mean_before).norm(), 0.0, 0.1);
  // Tolerance exceeded: refused with the tilt and what to do.
  o.max_tilt_deg = 0.5;
  const TurntableVerdict refused = EvaluateTurntable(RunSamples(OneRun(tilt_rad)), kModel, Entered(0.10, 120), o);
  EXPECT_FALSE(refused.level);
  EXPECT_TRUE(Contains(refused.reason, "the turntable is tilted 2 deg")) << refused.reason;
  EXPECT_TRUE(Contains(refused.reason, "tolerance 0.5 deg: level the turntable (a spirit level on "
                                       "its plate, turn its feet)")) << refused.reason;
}

TEST(TurntableStability, UnsteadySpeedIsCaught) {
  // The table speeds up from 108 to 120 rpm over the window.
  std::vector<Sample> samples;
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, 1.5);
  for (int k = 0; k < 1000; ++k) {
    const double t_s = k / 100.0;
    const double w = RpmToRadPerS(108.0 + 12.0 * t_s / 10.0);
    Sample s;
    s.t_s = t_s;
    s.raw_counts = kModel.Raw({-w * w * 0.10, 0.0, 9.80665}) +
                   Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    samples.push_back(s);
  }
  const TurntableVerdict v =
      EvaluateTurntable(samples, kModel, Entered(0.10, 120), TurntableStabilityOptions{});
  EXPECT_FALSE(v.steady);
  EXPECT_TRUE(Contains(v.reason, "speed not steady: centripetal went from 1")) << v.reason;
  EXPECT_GT(v.sub_window_centripetal_mps2.back(), v.sub_window_centripetal_mps2.front());
}

TEST(TurntableStability, PlanIsCheckedAgainstTheRange) {
  const AdcRange range = sim::DefaultScenario().adc.Range();
  const TurntableStabilityOptions options;
  EXPECT_EQ(CheckTurntablePlan(Entered(0.10, 120), kModel, range, options), "");
  const std::string fast = CheckTurntablePlan(Entered(0.15, 200), kModel, range, options);
  EXPECT_TRUE(Contains(fast, "planned 65.8 m/s^2 centripetal (200 rpm at 0.15 m) exceeds the "
                             "sensor's range on x")) << fast;
  const std::string cm = CheckTurntablePlan(Entered(10.0, 120), kModel, range, options);
  EXPECT_TRUE(Contains(cm, "10 m is an unusual radius: did you mean 0.1 m?")) << cm;
}

TEST(TurntableStability, SetupAndOptionsAreValidated) {
  EXPECT_TRUE(Contains(Entered(-1, 120).Validate(), "radius"));
  TurntableSetup skew = Entered(0.1, 120);
  skew.up_axis = skew.radial_axis;
  EXPECT_TRUE(Contains(skew.Validate(), "perpendicular"));
  TurntableStabilityOptions bad;
  bad.sub_windows = 1;
  EXPECT_TRUE(Contains(bad.Validate(), "sub_windows"));
}

}  // namespace
}  // namespace accelcal::turntable_stability_test
