// The clumsy bench: the scenario's technician (sim/technician.h) and the tilted table play each
// fault on demand. The truth is read from the bench itself (the scenario's model and the
// mounting), never from the code under test.
#include <cmath>

#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/technician.h"
#include "accelcal/acquire/source/sim_source.h"
#include "accelcal/app/wizard/leveling.h"
#include "accelcal/io/scenario_file.h"
#include "test_support.h"

namespace accelcal::clumsy_bench_test {
namespace {

using testing::Contains;

SimOptions Fast() {
  SimOptions o;
  o.speed = 0.0;
  o.bump_probability = 0.0;
  o.settle_s = 0.0;
  return o;
}

// The mean raw reading of the next `seconds` of samples.
Eigen::Vector3d MeanRaw(SimSource& source, double seconds, std::vector<Sample>* kept = nullptr) {
  std::vector<Sample> all;
  const double until = source.now_s() + seconds;
  while (source.now_s() < until) source.Read(1.0, &all);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Sample& s : all) sum += s.raw_counts;
  if (kept != nullptr) *kept = all;
  return sum / static_cast<double>(all.size());
}

TEST(ClumsyBench, ScenarioFileReadsTheTechnicianAndTheTable) {
  const std::string text = R"(
[sensor]
bias_counts = [2048, 2048, 2048]
scale_counts_per_mps2 = [34.8, 34.8, 34.8]
[adc]
bits = 12
[bench]
table_tilt_deg = [2.5, -1.5]
[technician]
leveling_gain = 0.7
[[technician.shake]]
from_s = 0
to_s = 20
rms_mps2 = 0.3
[[technician.mistake]]
asked_up = [-1, 0, 0]
up = [0, -1, 0]
[[technician.mistake]]
asked_radial = "+x"
asked_up_axis = "+z"
asked_radius_m = 0.05
radial = "+y"
up_axis = "+z"
after = 1
times = 2
[[technician.mistake]]
asked_up = [1, 0, 0]
bump_at_s = 3
bump_peak_mps2 = 4
[[capture]]
kind = "static"
label = "z up"
up = [0, 0, 1]
)";
  const sim::Scenario s = sim::ParseScenario(text, "clumsy.toml");
  EXPECT_EQ(s.bench.table_tilt_deg, Eigen::Vector2d(2.5, -1.5));
  EXPECT_DOUBLE_EQ(s.technician.leveling_gain, 0.7);
  ASSERT_EQ(s.technician.shakes.size(), 1u);
  EXPECT_DOUBLE_EQ(s.technician.shakes[0].rms_mps2, 0.3);
  ASSERT_EQ(s.technician.mistakes.size(), 3u);
  EXPECT_EQ(*s.technician.mistakes[0].up, Eigen::Vector3d(0, -1, 0));
  EXPECT_EQ(*s.technician.mistakes[1].radial, SensorAxis::kPlusY);
  EXPECT_EQ(s.technician.mistakes[1].after, 1);
  EXPECT_EQ(s.technician.mistakes[1].times, 2);
  EXPECT_DOUBLE_EQ(s.technician.mistakes[2].bump_at_s, 3.0);
}

TEST(ClumsyBench, BadTechnicianEntriesAreRefusedWithTheReason) {
  const std::string head = "[sensor]\nbias_counts = [0, 0, 0]\nscale_counts_per_mps2 = [1, 1, 1]\n"
                           "[adc]\nbits = 12\n[[capture]]\nkind = \"static\"\nlabel = \"z\"\nup = [0, 0, 1]\n";
  const auto error = [&](const std::string& extra) -> std::string {
    return testing::ExpectInputError([&] { sim::ParseScenario(head + extra, "x.toml"); }, extra).what();
  };
  EXPECT_TRUE(Contains(error("[[technician.mistake]]\nup = [0, 1, 0]\n"), "asked_up"));
  EXPECT_TRUE(Contains(error("[[technician.mistake]]\nasked_up = [0, 0, 1]\nradial = \"+x\"\nup_axis = \"+z\"\n"),
                       "static pose"));
  EXPECT_TRUE(Contains(error("[technician]\nleveling_gain = 1.5\n"), "leveling_gain"));
  EXPECT_TRUE(Contains(error("[[technician.shake]]\nfrom_s = 5\nto_s = 2\nrms_mps2 = 1\n"), "to_s"));
  EXPECT_TRUE(Contains(error("[technician]\nbogus = 1\n"), "bogus"));
}

TEST(ClumsyBench, TheTechnicianPutsTheWrongFaceUpOnceThenTheRightOne) {
  sim::Technician t;
  sim::Mistake m;
  m.asked_up = Eigen::Vector3d(-1, 0, 0);
  m.up = Eigen::Vector3d(0, -1, 0);
  t.mistakes = {m};
  sim::TechnicianPlay play(t);
  sim::CapturePlan asked;
  asked.up = Eigen::Vector3d(-1, 0, 0);
  EXPECT_EQ(play.Place(asked).placed.up, Eigen::Vector3d(0, -1, 0));
  EXPECT_EQ(play.Place(asked).placed.up, Eigen::Vector3d(-1, 0, 0));
  sim::CapturePlan other;
  other.up = Eigen::Vector3d(0, 0, 1);
  EXPECT_EQ(play.Place(other).placed.up, Eigen::Vector3d(0, 0, 1));
}

TEST(ClumsyBench, AWrongMountingReallyPutsTheCentripetalLoadOnTheOtherAxis) {
  sim::Scenario s = sim::DefaultScenario();
  sim::Mistake m;
  m.asked_radial = SensorAxis::kPlusX;
  m.asked_up_axis = SensorAxis::kPlusZ;
  m.radial = SensorAxis::kPlusY;
  m.up_axis = SensorAxis::kPlusZ;
  s.technician.mistakes = {m};
  SimSource source(s, Fast());
  source.PlaceTurntable(0.10, 120.0, SensorAxis::kPlusX, SensorAxis::kPlusZ);
  MeanRaw(source, 1.0);
  const Eigen::Vector3d f = s.sensor.model.Calibrate(MeanRaw(source, 5.0));
  const double c = std::pow(RpmToRadPerS(120.0), 2) * 0.10;
  EXPECT_NEAR(f.y(), -c, 0.05 * c);  // +y points outward: it feels -w^2 r
  EXPECT_NEAR(f.x(), 0.0, 0.5);
  // Asked again: mounted as asked.
  source.PlaceTurntable(0.10, 120.0, SensorAxis::kPlusX, SensorAxis::kPlusZ);
  MeanRaw(source, 1.0);
  const Eigen::Vector3d g = s.sensor.model.Calibrate(MeanRaw(source, 5.0));
  EXPECT_NEAR(g.x(), -c, 0.05 * c);
}

TEST(ClumsyBench, AWrongRadiusAndAKnockArePlayed) {
  sim::Scenario s = sim::DefaultScenario();
  sim::Mistake radius;
  radius.asked_radial = SensorAxis::kPlusX;
  radius.asked_up_axis = SensorAxis::kPlusZ;
  radius.radius_m = 0.10;
  sim::Mistake knock;
  knock.asked_up = Eigen::Vector3d::UnitZ();
  knock.bump_at_s = 2.0;
  knock.bump_peak_mps2 = 4.0;
  s.technician.mistakes = {radius, knock};
  SimSource source(s, Fast());
  source.PlaceTurntable(0.05, 120.0, SensorAxis::kPlusX, SensorAxis::kPlusZ);
  MeanRaw(source, 1.0);
  const Eigen::Vector3d f = s.sensor.model.Calibrate(MeanRaw(source, 5.0));
  EXPECT_NEAR(-f.x(), std::pow(RpmToRadPerS(120.0), 2) * 0.10, 0.5);  // twice the asked 0.05 m
  const long before = source.bumps_scheduled();
  source.PlaceStatic(Eigen::Vector3d::UnitZ(), 0.0);
  EXPECT_EQ(source.bumps_scheduled(), before + 1);
  std::vector<Sample> samples;
  MeanRaw(source, 4.0, &samples);
  double largest = 0.0;  // the knock, horizontal: far beyond the 1.5-count noise
  for (const Sample& x : samples)
    largest = std::max(largest, (x.raw_counts - s.sensor.model.bias_counts).head<2>().norm());
  EXPECT_GT(largest, 60.0);
}

TEST(ClumsyBench, TheBenchShakesOnlyInItsWindow) {
  sim::Scenario s = sim::DefaultScenario();
  s.technician.shakes = {{0.0, 10.0, 0.3}};
  SimSource source(s, Fast());
  std::vector<Sample> shaking, still;
  MeanRaw(source, 5.0, &shaking);
  MeanRaw(source, 6.0);
  MeanRaw(source, 5.0, &still);
  const double shaking_std = ComputeStats(shaking).StdCounts().x();
  const double still_std = ComputeStats(still).StdCounts().x();
  EXPECT_NEAR(shaking_std, std::hypot(0.3 * 34.62, 1.5), 1.5);
  EXPECT_NEAR(still_std, 1.5, 0.3);
}

// The reversal of leveling.h on the tilted table measures its tilt, and the feet turned by the
// technician as advised bring it within tolerance: the leveling loop converges.
TEST(ClumsyBench, TheTiltedTableIsMeasuredAndConvergesAsTheFeetAreTurned) {
  sim::Scenario s = sim::DefaultScenario();
  s.bench.table_tilt_deg = Eigen::Vector2d(3.0, -2.0);
  s.bench.placement_error_deg = 0.0;
  SimSource source(s, Fast());
  const SensorModel rough = s.sensor.model;  // only the reversal is tested here
  int rounds = 0;
  for (; rounds < 6; ++rounds) {
    source.PlaceStatic(Eigen::Vector3d::UnitZ(), 0.0);
    const Eigen::Vector3d first = MeanRaw(source, 3.0);
    source.PlaceStatic(Eigen::Vector3d::UnitZ(), M_PI);
    const Eigen::Vector3d turned = MeanRaw(source, 3.0);
    const Eigen::Vector2d tilt = ReversalTiltDeg(first, turned, rough);
    if (rounds == 0) {
      EXPECT_NEAR(tilt.x(), 3.0, 0.1);
      EXPECT_NEAR(tilt.y(), -2.0, 0.1);
    }
    if (LevelingAdvice(tilt, 0.3).empty()) break;
    source.AdjustTableFeet(tilt);
  }
  EXPECT_GE(rounds, 1);
  EXPECT_LT(rounds, 6);
  EXPECT_LT(source.bench_state().table_tilt_deg().norm(), 0.3);
}

TEST(ClumsyBench, TheTurntableIsLeveledByAShareOfItsTilt) {
  sim::Scenario s = sim::DefaultScenario();
  s.effects.turntable_tilt_rad = 0.04;
  s.technician.leveling_gain = 0.9;
  SimSource source(s, Fast());
  source.LevelTurntable();
  EXPECT_NEAR(source.bench_state().turntable_tilt_rad(), 0.004, 1e-12);
}

}  // namespace
}  // namespace accelcal::clumsy_bench_test
