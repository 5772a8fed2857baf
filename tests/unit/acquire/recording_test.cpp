// VirtualBench::SimulateRecording: a hand-turned continuous record of the static poses.
#include <cmath>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/acquire/sim/virtual_bench.h"

namespace accelcal::sim {
namespace {

Scenario StaticOnly() {
  Scenario s = DefaultScenario();
  s.captures.resize(9);  // the nine static poses
  return s;
}

std::vector<Sample> Between(const std::vector<Sample>& all, double from_s, double to_s) {
  std::vector<Sample> out;
  for (const Sample& s : all) {
    if (s.t_s >= from_s && s.t_s < to_s) out.push_back(s);
  }
  return out;
}

TEST(Recording, TimelineIsQuietStartThenMovesAndHolds) {
  VirtualBench bench(StaticOnly());
  const BenchSpec& b = bench.scenario().bench;
  const std::vector<Sample> samples = bench.SimulateRecording();
  // 30 s quiet start (longer than the 10 s pose), then 8 x (4 s move + 10 s hold).
  const double total_s = b.recording_quiet_start_s + 8 * (b.move_s + 10.0);
  ASSERT_EQ(samples.size(), static_cast<std::size_t>(std::lround(total_s * 100.0)));
  EXPECT_EQ(samples.front().t_s, 0.0);
  EXPECT_NEAR(samples[1].t_s - samples[0].t_s, 0.01, 1e-9);
  EXPECT_EQ(samples.front().temp_c, 25.0);
}

TEST(Recording, QuietStartShowsOnlyNoise) {
  VirtualBench bench(StaticOnly());
  const Scenario& s = bench.scenario();
  const std::vector<Sample> quiet = Between(bench.SimulateRecording(), 0.0, 30.0);
  ASSERT_EQ(quiet.size(), 3000u);
  const CaptureStats st = ComputeStats(quiet);
  for (int i = 0; i < 3; ++i) EXPECT_LT(st.StdCounts()(i), 1.2 * s.sensor.noise_counts(i) + 0.1);
  const Eigen::Vector3d f = s.sensor.model.Calibrate(st.mean_counts);
  EXPECT_NEAR(f.norm(), s.bench.gravity_mps2, 0.02);
  EXPECT_GT(f.normalized().dot(s.captures[0].up), std::cos(0.05));
}

TEST(Recording, HoldsReadTheirPosesAndMovesAreRestless) {
  VirtualBench bench(StaticOnly());
  const Scenario& s = bench.scenario();
  const std::vector<Sample> samples = bench.SimulateRecording();
  double start_s = 30.0;
  for (int i = 1; i < 9; ++i) {
    SCOPED_TRACE(s.captures[i].label);
    // The move: the hand's jitter shakes |f| well beyond what noise alone would (~0.05 m/s^2).
    double sum = 0.0, sum2 = 0.0;
    const std::vector<Sample> move = Between(samples, start_s, start_s + 4.0);
    for (const Sample& smp : move) {
      const double n = s.sensor.model.Calibrate(smp.raw_counts).norm();
      sum += n;
      sum2 += n * n;
    }
    const double mean = sum / static_cast<double>(move.size());
    EXPECT_GT(std::sqrt(sum2 / static_cast<double>(move.size()) - mean * mean), 0.2);
    // The hold: gravity along this pose's `up`.
    const CaptureStats hold = ComputeStats(Between(samples, start_s + 4.0, start_s + 14.0));
    EXPECT_EQ(hold.n, 1000);
    const Eigen::Vector3d f = s.sensor.model.Calibrate(hold.mean_counts);
    EXPECT_NEAR(f.norm(), s.bench.gravity_mps2, 0.02);
    EXPECT_GT(f.normalized().dot(s.captures[i].up), std::cos(0.05));
    start_s += 14.0;
  }
}

TEST(Recording, BumpLandsInItsPosesHold) {
  Scenario s = StaticOnly();
  s.sensor.noise_counts.setZero();
  s.effects.bumps = {Bump{1, 2.0, 4.0, 0.2}};  // pose 1's hold starts at 30 + 4 s
  VirtualBench bench(s);
  double peak_mps2 = 0.0;
  for (const Sample& smp : Between(bench.SimulateRecording(), 34.0, 44.0)) {
    const double excess = std::abs(s.sensor.model.Calibrate(smp.raw_counts).norm() - 9.80665);
    if (smp.t_s < 36.0 || smp.t_s > 36.2) {
      EXPECT_LT(excess, 0.05) << smp.t_s;
    } else {
      peak_mps2 = std::max(peak_mps2, excess);
    }
  }
  // |g z + a| - g for a horizontal a of 4 m/s^2 is about a^2 / 2g.
  EXPECT_GT(peak_mps2, 0.6);
}

TEST(Recording, IsDeterministicPerSeed) {
  VirtualBench a(StaticOnly());
  VirtualBench b(StaticOnly());
  const std::vector<Sample> x = a.SimulateRecording();
  const std::vector<Sample> y = b.SimulateRecording();
  ASSERT_EQ(x.size(), y.size());
  for (std::size_t k = 0; k < x.size(); ++k) ASSERT_EQ(x[k].raw_counts, y[k].raw_counts) << k;
}

TEST(Recording, RefusesTurntableCaptures) {
  VirtualBench bench(DefaultScenario());
  try {
    bench.SimulateRecording();
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("static poses only"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace accelcal::sim
