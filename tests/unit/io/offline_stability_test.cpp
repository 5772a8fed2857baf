#include "accelcal/acquire/capture_engine/offline_stability.h"

#include <gtest/gtest.h>

#include "accelcal/calibration/capture_screening.h"
#include "accelcal/calibration/fit/calibration_fit.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/acquire/sim/virtual_bench.h"
#include "test_support.h"

namespace accelcal {
namespace {

using testing::Contains;

TEST(OfflineStability, CleanSetsKeepEveryCapture) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    sim::Scenario scenario = sim::DefaultScenario();
    scenario.bench.seed = seed;
    std::vector<Capture> captures = sim::VirtualBench(scenario).SimulateCaptureSet();
    const NoiseFloor floor = ScreenStaticStability(captures, OfflineStabilityOptions{});
    EXPECT_NEAR(floor.std_counts.z(), 1.7, 0.15);
    for (const Capture& c : captures) EXPECT_TRUE(c.used()) << c.label << ": " << c.rejection_reason;
  }
}

TEST(OfflineStability, BumpedCaptureIsLeftOutAndTheFitConverges) {
  sim::Scenario scenario = sim::DefaultScenario();
  scenario.effects.bumps.push_back({2, 6.0, 1.5, 0.1});  // "x up", 6 s in
  std::vector<Capture> captures = sim::VirtualBench(scenario).SimulateCaptureSet();
  ScreeningOptions screening;
  screening.adc_range = scenario.adc.Range();
  ScreenCaptures(captures, screening);
  ScreenStaticStability(captures, OfflineStabilityOptions{});
  for (const Capture& c : captures) EXPECT_EQ(c.used(), c.id != 3) << c.label;
  EXPECT_TRUE(Contains(captures[2].rejection_reason, "not still: ")) << captures[2].rejection_reason;

  FitOptions options;
  options.gravity = GravitySpec::Given(scenario.bench.gravity_mps2);
  const FitSummary s = FitCalibration(captures, options);
  ASSERT_TRUE(s.IsUsable()) << s.FullReport();
  EXPECT_EQ(s.num_captures, 17);
  const Calibration cal = MakeCalibration(s, options.gravity, captures, "bumped.csv");
  EXPECT_FALSE(cal.captures[2].used);
  EXPECT_EQ(cal.captures[2].reason, captures[2].rejection_reason);
}

TEST(OfflineStability, GivenFloorIsUsedAndTurntableRunsAreLeftAlone) {
  std::vector<Capture> captures = sim::VirtualBench(sim::DefaultScenario()).SimulateCaptureSet();
  OfflineStabilityOptions options;
  options.noise_floor_counts = Eigen::Vector3d(0.3, 0.3, 0.3);  // far too low: all static fail
  const NoiseFloor floor = ScreenStaticStability(captures, options);
  EXPECT_EQ(floor.source, "given");
  for (const Capture& c : captures) EXPECT_EQ(c.used(), c.kind == CaptureKind::kTurntable);
}

}  // namespace
}  // namespace accelcal
