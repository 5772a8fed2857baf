// sim: the virtual bench as a live source. Placements turn gravity in the samples, speed 0
// delivers many seconds at once, and the truth model turns a still period back into |f| = g.
#include "accelcal/acquire/source/sim_source.h"

#include <chrono>
#include <cmath>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/acquire/sim/scenario.h"
#include "source_test_support.h"

namespace accelcal {
namespace {

SimOptions Fast() {
  SimOptions o;
  o.speed = 0.0;
  o.bump_probability = 0.0;
  return o;
}

// Reads until the simulated clock passes until_s; returns the samples with t in [from_s, until_s).
std::vector<Sample> SamplesBetween(SimSource& source, double from_s, double until_s) {
  std::vector<Sample> all;
  while (source.now_s() < until_s) source.Read(1.0, &all);
  std::vector<Sample> kept;
  for (const Sample& s : all)
    if (s.t_s >= from_s && s.t_s < until_s) kept.push_back(s);
  return kept;
}

// Mean specific force of `samples` in the platform frame, by the scenario's true model, m/s^2.
Eigen::Vector3d MeanPlatformMps2(const SimSource& source, const std::vector<Sample>& samples) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Sample& s : samples) sum += source.scenario().sensor.model.Calibrate(s.raw_counts);
  return sum / static_cast<double>(samples.size());
}

TEST(SimSourceTest, FastModeDeliversManySecondsWithAContinuousClock) {
  SimSource source(sim::DefaultScenario(), Fast());
  std::vector<Sample> samples;
  ASSERT_TRUE(testing::ReadUntil(source, &samples,
                                 [](const SourceStatus& s) { return s.samples_total >= 6000; }));
  EXPECT_EQ(samples.front().t_s, 0.0);
  for (size_t i = 1; i < samples.size(); ++i)
    ASSERT_NEAR(samples[i].t_s - samples[i - 1].t_s, 0.01, 1e-9) << "at " << i;
  EXPECT_NEAR(source.status().rate_hz, 100.0, 1e-6);
  EXPECT_EQ(source.status().link, LinkState::kUp);
  EXPECT_EQ(source.status().gaps, 0);
}

TEST(SimSourceTest, StillPeriodCalibratesToGravityByTheTruthModel) {
  SimSource source(sim::DefaultScenario(), Fast());
  const std::vector<Sample> still = SamplesBetween(source, 0.0, 10.0);
  const Eigen::Vector3d f = MeanPlatformMps2(source, still);
  EXPECT_NEAR(f.norm(), source.scenario().bench.gravity_mps2, 0.01);
  EXPECT_GT(f.z(), 9.7);  // level, +z up
}

TEST(SimSourceTest, PlacementTurnsGravityInTheSamples) {
  SimSource source(sim::DefaultScenario(), Fast());
  SamplesBetween(source, 0.0, 2.0);
  ASSERT_NE(source.bench(), nullptr);
  const double placed_s = source.now_s();
  source.bench()->PlaceStatic(Eigen::Vector3d(-1.0, 0.0, 0.0), 0.0);
  // Moving while it settles...
  const std::vector<Sample> settling = SamplesBetween(source, placed_s, placed_s + 1.5);
  // ...then still with -x up, gravity where the pose says (placement error ~0.5 deg).
  const std::vector<Sample> still = SamplesBetween(source, placed_s + 2.0, placed_s + 12.0);
  const Eigen::Vector3d f = MeanPlatformMps2(source, still);
  const double g = source.scenario().bench.gravity_mps2;
  EXPECT_NEAR(f.norm(), g, 0.01);
  EXPECT_LT(f.x(), -0.99 * g);
  const Eigen::Vector3d first = source.scenario().sensor.model.Calibrate(settling.front().raw_counts);
  EXPECT_GT(first.z(), 9.0) << "the move starts from the previous pose";
  // The truth of the mounting is visible for tests: its up is -x, up to the placement error.
  const Eigen::Vector3d up_platform = source.mounting().platform_rotation.transpose() * Eigen::Vector3d::UnitZ();
  EXPECT_GT(-up_platform.x(), std::cos(5.0 * M_PI / 180.0));
}

TEST(SimSourceTest, TurntableAddsTheCentripetalTerm) {
  SimSource source(sim::DefaultScenario(), Fast());
  source.PlaceTurntable(0.1, 120.0, sim::SensorAxis::kPlusX, sim::SensorAxis::kPlusZ);
  const double placed_s = source.now_s();
  const std::vector<Sample> spinning = SamplesBetween(source, placed_s + 2.0, placed_s + 10.0);
  double mean_norm = 0.0;
  for (const Sample& s : spinning)
    mean_norm += source.scenario().sensor.model.Calibrate(s.raw_counts).norm();
  mean_norm /= static_cast<double>(spinning.size());
  const double w = RpmToRadPerS(120.0), g = source.scenario().bench.gravity_mps2;
  EXPECT_NEAR(mean_norm, std::hypot(g, w * w * 0.1), 0.05);
  source.StopTurntable();
  const std::vector<Sample> stopped = SamplesBetween(source, source.now_s() + 2.0, source.now_s() + 7.0);
  EXPECT_NEAR(MeanPlatformMps2(source, stopped).norm(), g, 0.02);
}

TEST(SimSourceTest, BumpsDisturbTheStillPeriod) {
  SimOptions options = Fast();
  options.bump_probability = 1.0;
  SimSource source(sim::DefaultScenario(), options);
  SamplesBetween(source, 0.0, 1.0);
  const double placed_s = source.now_s();
  source.PlaceStatic(Eigen::Vector3d(0.0, 1.0, 0.0), 0.0);
  EXPECT_EQ(source.bumps_scheduled(), 1);
  const std::vector<Sample> after = SamplesBetween(source, placed_s + options.settle_s, placed_s + 10.0);
  double worst = 0.0;
  const double g = source.scenario().bench.gravity_mps2;
  for (const Sample& s : after)
    worst = std::max(worst, std::abs(source.scenario().sensor.model.Calibrate(s.raw_counts).norm() - g));
  EXPECT_GT(worst, 0.5) << "a bump of 2..5 m/s^2 shows";
}

TEST(SimSourceTest, RealTimeMultipliedBySpeedDeliversInOrder) {
  SimOptions options;
  options.speed = 50.0;
  SimSource source(sim::DefaultScenario(), options);
  std::vector<Sample> samples;
  ASSERT_TRUE(testing::ReadUntil(source, &samples,
                                 [](const SourceStatus& s) { return s.samples_total >= 500; }));
  for (size_t i = 1; i < samples.size(); ++i) ASSERT_GT(samples[i].t_s, samples[i - 1].t_s);
}

// Issue 18: at 10 kHz the paced source woke for every sample that fell due, and its reader (the
// wizard's loop) with it: a quarter of a core. Each paced read now waits at least 5 ms for a
// burst, so 0.2 s of wall time holds at most ~40 reads however fast or slow the machine (the
// old source made one per sample: ~2000), and the samples still come in order with none lost.
TEST(SimSourceTest, APacedFastStreamComesInBurstsNotOneReadPerSample) {
  sim::Scenario scenario = sim::DefaultScenario();
  scenario.sensor.rate_hz = 10000.0;
  SimOptions options;
  options.speed = 1.0;
  options.bump_probability = 0.0;
  SimSource source(scenario, options);
  std::vector<Sample> samples;
  int reads = 0;
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(200)) {
    source.Read(1.0, &samples);
    ++reads;
  }
  EXPECT_LE(reads, 42);
  ASSERT_FALSE(samples.empty());
  for (size_t i = 1; i < samples.size(); ++i)
    ASSERT_NEAR(samples[i].t_s - samples[i - 1].t_s, 1e-4, 1e-9) << "sample " << i;
}

TEST(SimSourceTest, BadPlacementsAreRefused) {
  SimSource source(sim::DefaultScenario(), Fast());
  EXPECT_THROW(source.PlaceStatic(Eigen::Vector3d::Zero(), 0.0), Error);
  EXPECT_THROW(source.PlaceTurntable(0.1, 120.0, sim::SensorAxis::kPlusX, sim::SensorAxis::kMinusX),
               Error);
  EXPECT_THROW(source.PlaceTurntable(-0.1, 120.0, sim::SensorAxis::kPlusX, sim::SensorAxis::kPlusZ),
               Error);
  SimOptions bad;
  bad.speed = 0.5;
  EXPECT_THROW(SimSource(sim::DefaultScenario(), bad), Error);
}

}  // namespace
}  // namespace accelcal
