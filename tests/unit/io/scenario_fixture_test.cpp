// A scenario's [fixture] (acquire/sim/bench_fixture.h): boards with their own truth, mounting and
// faults read from the scenario file; the truths drawn for the others; --sensors N's row.
#include "accelcal/acquire/sim/bench_fixture.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "test_support.h"

#include "accelcal/base/error.h"
#include "accelcal/acquire/sim/virtual_bench.h"
#include "accelcal/io/scenario_file.h"

namespace accelcal::sim::scenario_fixture_test {
namespace {

using testing::Contains;

const std::string kBase = R"([sensor]
bias_counts = [2048, 2048, 2048]
scale_counts_per_mps2 = [34.8, 34.8, 34.8]
noise_counts = [1, 1, 1]

[adc]
bits = 12

[[capture]]
kind = "static"
label = "z up"
up = [0, 0, 1]
)";

const std::string kFixture = R"(
[fixture]
name = "plate 4"
bias_spread_counts = 10
scale_spread = 0.01
misalignment_spread_rad = 0.002

[[fixture.board]]
serial = "B1"
offset_m = [-0.05, 0, 0]

[[fixture.board]]
serial = "B2"
x = "+y"
y = "-x"
bias_counts = [2000, 2010, 2020]
scale_counts_per_mps2 = [34, 35, 36]
misalignment_rad = { yz = 0.001 }

[[fixture.board]]
serial = "B3"
fault = "dead"
dead_from_s = 12.5

[[fixture.board]]
serial = "B4"
fault = "loose"
loose_deg = 4
loose_rock_s = 12
mounted_x = "-x"
mounted_y = "-y"
)";

InputError ParseFails(const std::string& text) {
  return testing::ExpectInputError([&] { ParseScenario(text, "s.toml"); }, text);
}

TEST(ScenarioFixture, WithoutOneTheBenchHasOneSensor) {
  EXPECT_FALSE(ParseScenario(kBase, "s.toml").fixture.has_value());
}

TEST(ScenarioFixture, ReadsEachBoard) {
  const Scenario s = ParseScenario(kBase + kFixture, "s.toml");
  ASSERT_TRUE(s.fixture.has_value());
  const BenchFixture& f = *s.fixture;
  EXPECT_EQ(f.name, "plate 4");
  EXPECT_DOUBLE_EQ(f.bias_spread_counts, 10.0);
  ASSERT_EQ(f.boards.size(), 4u);
  EXPECT_EQ(f.boards[0].declared.serial, "B1");
  EXPECT_DOUBLE_EQ(f.boards[0].declared.offset_m.x(), -0.05);
  EXPECT_FALSE(f.boards[0].model.has_value());
  EXPECT_EQ(f.boards[0].fault, BoardFault::kNone);
  // B2: turned as declared, with its own truth.
  EXPECT_EQ(SensorAxisOf(f.boards[1].declared, SensorAxis::kPlusX), SensorAxis::kMinusY);
  EXPECT_TRUE(f.boards[1].mounted_to_plate.isApprox(f.boards[1].declared.sensor_to_plate));
  ASSERT_TRUE(f.boards[1].model.has_value());
  EXPECT_DOUBLE_EQ(f.boards[1].model->bias_counts.y(), 2010.0);
  EXPECT_DOUBLE_EQ(f.boards[1].model->scale_counts_per_mps2.z(), 36.0);
  EXPECT_DOUBLE_EQ(f.boards[1].model->a_yz_rad, 0.001);
  EXPECT_EQ(f.boards[2].fault, BoardFault::kDead);
  EXPECT_DOUBLE_EQ(f.boards[2].dead_from_s, 12.5);
  // B4: loose, and put in turned half a turn about z although the file says square.
  EXPECT_EQ(f.boards[3].fault, BoardFault::kLoose);
  EXPECT_DOUBLE_EQ(f.boards[3].loose_deg, 4.0);
  EXPECT_DOUBLE_EQ(f.boards[3].loose_rock_s, 12.0);
  EXPECT_DOUBLE_EQ(f.boards[0].loose_rock_s, 3.0);  // the default
  EXPECT_TRUE(f.boards[3].declared.sensor_to_plate.isIdentity());
  EXPECT_TRUE(f.boards[3].mounted_to_plate.isApprox(
      Eigen::Vector3d(-1, -1, 1).asDiagonal().toDenseMatrix()));
  const Fixture declared = f.Declared();
  EXPECT_EQ(declared.name, "plate 4");
  ASSERT_EQ(declared.sensors.size(), 4u);
  EXPECT_EQ(declared.sensors[3].serial, "B4");
  EXPECT_TRUE(declared.sensors[3].sensor_to_plate.isIdentity());
}

// Drawn truths: within the spreads around [sensor]'s, different from board to board, the same
// for the same seed, and a board's draw unchanged when another board is added.
TEST(ScenarioFixture, DrawnTruthsStayWithinTheSpreads) {
  const Scenario s = ParseScenario(kBase + kFixture, "s.toml");
  const std::vector<SensorModel> truths = FixtureTruths(*s.fixture, s.sensor.model, 7);
  ASSERT_EQ(truths.size(), 4u);
  EXPECT_DOUBLE_EQ(truths[1].bias_counts.x(), 2000.0);  // its own, as given
  for (std::size_t i : {0u, 2u, 3u}) {
    const SensorModel& m = truths[i];
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(std::abs(m.bias_counts(a) - 2048.0), 10.0);
      EXPECT_LE(std::abs(m.scale_counts_per_mps2(a) / 34.8 - 1.0), 0.01 + 1e-12);
    }
    EXPECT_LE(std::abs(m.a_yz_rad), 0.002);
    EXPECT_LE(std::abs(m.a_zy_rad), 0.002);
    EXPECT_LE(std::abs(m.a_zx_rad), 0.002);
  }
  EXPECT_NE(truths[0].bias_counts.x(), truths[2].bias_counts.x());
  EXPECT_EQ(FixtureTruths(*s.fixture, s.sensor.model, 7)[3].bias_counts,
            truths[3].bias_counts);
  EXPECT_NE(FixtureTruths(*s.fixture, s.sensor.model, 8)[3].bias_counts, truths[3].bias_counts);
  BenchFixture more = *s.fixture;
  more.boards.push_back(more.boards[0]);
  more.boards.back().declared.serial = "B5";
  EXPECT_EQ(FixtureTruths(more, s.sensor.model, 7)[2].bias_counts, truths[2].bias_counts);
}

TEST(ScenarioFixture, RowOfBoardsForSensorsN) {
  const BenchFixture row = RowOfBoards(3);
  ASSERT_EQ(row.boards.size(), 3u);
  EXPECT_EQ(row.boards[0].declared.serial, "SIM01");
  EXPECT_EQ(row.boards[2].declared.serial, "SIM03");
  EXPECT_NEAR(row.boards[0].declared.offset_m.x(), -0.03, 1e-15);
  EXPECT_NEAR(row.boards[1].declared.offset_m.norm(), 0.0, 1e-15);
  EXPECT_NEAR(row.boards[2].declared.offset_m.x(), 0.03, 1e-15);
  for (const FixtureBoard& b : row.boards) EXPECT_EQ(b.fault, BoardFault::kNone);
  EXPECT_EQ(row.Validate(), "");
  EXPECT_NEAR(RowOfBoards(1).boards[0].declared.offset_m.norm(), 0.0, 1e-15);
  EXPECT_THROW(RowOfBoards(0), Error);
  EXPECT_THROW(RowOfBoards(65), Error);
}

// Until the fixture bench exists, the one-sensor bench refuses a plate rather than simulate
// one sensor of it.
TEST(ScenarioFixture, TheOneSensorBenchRefusesAPlate) {
  try {
    VirtualBench bench(ParseScenario(kBase + kFixture, "s.toml"));
    ADD_FAILURE() << "a plate of 4 boards simulated as one sensor";
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "s.toml: its [fixture] of 4 boards")) << e.what();
  }
}

TEST(ScenarioFixture, RefusesWhatIsWrongWhereItIs) {
  EXPECT_TRUE(Contains(ParseFails(kBase + "[fixture]\nname = \"x\"\n").what(),
                       "no [[fixture.board]]"));
  const InputError fault =
      ParseFails(kBase + "[[fixture.board]]\nserial = \"A\"\nfault = \"wobbly\"\n");
  EXPECT_TRUE(Contains(fault.what(), "fixture.board 1.fault")) << fault.what();
  EXPECT_TRUE(Contains(fault.what(), "wobbly")) << fault.what();
  EXPECT_TRUE(Contains(
      ParseFails(kBase + "[[fixture.board]]\nserial = \"A\"\ndead_from_s = 3\n").what(),
      "only a board with fault = \"dead\""));
  EXPECT_TRUE(Contains(
      ParseFails(kBase + "[[fixture.board]]\nserial = \"A\"\nloose_rock_s = 20\n").what(),
      "only a board with fault = \"loose\" has loose_rock_s"));
  EXPECT_TRUE(Contains(
      ParseFails(kBase + "[[fixture.board]]\nserial = \"A\"\nmounted_x = \"+z\"\nmounted_y = \"-z\"\n")
          .what(),
      "fixture.board 1.mounted_y"));
  EXPECT_TRUE(Contains(
      ParseFails(kBase + "[[fixture.board]]\nserial = \"A\"\n[[fixture.board]]\nserial = \"A\"\n")
          .what(),
      "serial 'A' is already another sensor's"));
  EXPECT_TRUE(Contains(
      ParseFails(kBase + "[[fixture.board]]\nserial = \"A\"\nbias_counts = [1, 2, 3]\n").what(),
      "scale_counts_per_mps2"));
  EXPECT_TRUE(Contains(
      ParseFails(kBase + "[[fixture.board]]\nserial = \"A\"\nsource = \"tcp:h:1\"\n").what(),
      "source"));
}

}  // namespace
}  // namespace accelcal::sim::scenario_fixture_test
