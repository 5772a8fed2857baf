// Several sensors from one source (issue 31): the fixture bench as a live source (each board
// its own truth, mounting, offset on the turntable; a dead board silent while the others go on;
// a loose one moving after the plate settled), a text line of 3N columns, one link per sensor.
// The expected forces are worked here from the geometry, not taken from the bench's code.
#include <unistd.h>

#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/base/fixture.h"
#include "accelcal/acquire/sim/bench_fixture.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/acquire/source/fixture_sim_source.h"
#include "accelcal/acquire/source/sensor_set_spec.h"

namespace accelcal::sensor_set_source_test {
namespace {

constexpr double kG = 9.80665;

SimOptions Fast() {
  SimOptions o;
  o.speed = 0.0;
  o.bump_probability = 0.0;
  o.settle_s = 0.5;
  return o;
}

sim::Scenario PlateOf(sim::BenchFixture boards) {
  sim::Scenario s = sim::DefaultScenario();
  s.fixture = std::move(boards);
  return s;
}

// Reads until sensor 0's (or any live sensor's) clock passes until_s; keeps t in [from, until).
SensorSetSamples Between(FixtureSimSource& source, double from_s, double until_s) {
  SensorSetSamples all;
  while (source.bench()->now_s() < until_s) source.Read(1.0, &all);
  SensorSetSamples kept;
  kept.Resize(all.per_sensor.size());
  for (std::size_t i = 0; i < all.per_sensor.size(); ++i)
    for (const Sample& s : all.per_sensor[i])
      if (s.t_s >= from_s && s.t_s < until_s) kept.per_sensor[i].push_back(s);
  return kept;
}

// Mean specific force the board felt, in its own axes, by its true model, m/s^2.
Eigen::Vector3d MeanMps2(const FixtureSimSource& source, std::size_t board,
                         const std::vector<Sample>& samples) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Sample& s : samples) sum += source.truth(board).Calibrate(s.raw_counts);
  return sum / static_cast<double>(samples.size());
}

TEST(FixtureSimSource, EveryBoardOnOneClockThroughItsOwnTruth) {
  FixtureSimSource source(PlateOf(sim::RowOfBoards(4)), Fast());
  ASSERT_EQ(source.sensor_count(), 4u);
  EXPECT_EQ(source.fixture().sensors[2].serial, "SIM03");
  const SensorSetSamples got = Between(source, 0.5, 3.0);
  for (std::size_t i = 0; i < 4; ++i) {
    ASSERT_EQ(got.per_sensor[i].size(), got.per_sensor[0].size());
    EXPECT_EQ(got.per_sensor[i].front().t_s, got.per_sensor[0].front().t_s);
    // Resting level: +g along each board's z (placement error a fraction of a degree).
    const Eigen::Vector3d f = MeanMps2(source, i, got.per_sensor[i]);
    EXPECT_NEAR(f.norm(), kG, 0.02);
    EXPECT_GT(f.z(), 0.999 * kG);
  }
  // Truths differ board to board (drawn within the spreads), and so do their raw readings.
  EXPECT_NE(source.truth(0).bias_counts, source.truth(1).bias_counts);
}

TEST(FixtureSimSource, ABoardTurnedOnThePlateFeelsThePlatePoseInItsOwnAxes) {
  sim::BenchFixture plate = sim::RowOfBoards(2);
  // Board 2: its x along the plate's +y, its y along the plate's -x (turned 90 deg about z).
  plate.boards[1].declared.sensor_to_plate = SensorToPlate(SensorAxis::kPlusY, SensorAxis::kMinusX);
  plate.boards[1].mounted_to_plate = plate.boards[1].declared.sensor_to_plate;
  FixtureSimSource source(PlateOf(plate), Fast());
  source.bench()->PlaceStatic(Eigen::Vector3d::UnitX(), 0.0);  // the plate's +x up
  const double t0 = source.bench()->now_s();
  const SensorSetSamples got = Between(source, t0 + 1.0, t0 + 3.0);
  const Eigen::Vector3d f0 = MeanMps2(source, 0, got.per_sensor[0]);
  const Eigen::Vector3d f1 = MeanMps2(source, 1, got.per_sensor[1]);
  EXPECT_GT(f0.x(), 0.999 * kG);   // square board: up along its +x
  EXPECT_LT(f1.y(), -0.999 * kG);  // turned board: the plate's +x is its -y
}

TEST(FixtureSimSource, EachBoardHasItsOwnTurntableRadius) {
  sim::BenchFixture plate = sim::RowOfBoards(1);
  sim::FixtureBoard outer;
  outer.declared.serial = "OUT";
  outer.declared.offset_m = Eigen::Vector3d(0.05, 0.0, 0.0);  // 5 cm further out along x
  plate.boards.push_back(outer);
  plate.boards[0].declared.offset_m = Eigen::Vector3d::Zero();
  FixtureSimSource source(PlateOf(plate), Fast());
  const double radius_m = 0.10;
  const double rpm = 120.0;
  source.bench()->PlaceTurntable(radius_m, rpm, SensorAxis::kPlusX, SensorAxis::kPlusZ);
  const double t0 = source.bench()->now_s();
  const SensorSetSamples got = Between(source, t0 + 1.5, t0 + 4.0);
  const double w = rpm * 2.0 * M_PI / 60.0;
  // Centripetal along -x of each board (inward), by its own radius; gravity along z.
  const Eigen::Vector3d f0 = MeanMps2(source, 0, got.per_sensor[0]);
  const Eigen::Vector3d f1 = MeanMps2(source, 1, got.per_sensor[1]);
  const auto relative = [](double got_v, double want) { return std::abs(got_v - want) / want; };
  EXPECT_LT(relative(f0.norm(), std::hypot(kG, w * w * 0.10)), 0.005);
  EXPECT_LT(relative(f1.norm(), std::hypot(kG, w * w * 0.15)), 0.005);
  EXPECT_NEAR(f1.x() - f0.x(), -w * w * 0.05, 0.02 * w * w * 0.05 + 0.01);
}

TEST(FixtureSimSource, ADeadBoardIsSilentAndNamedWhileTheOthersGoOn) {
  sim::BenchFixture plate = sim::RowOfBoards(3);
  plate.boards[1].fault = sim::BoardFault::kDead;
  plate.boards[1].dead_from_s = 1.0;
  SimOptions o = Fast();
  FixtureSimSource source(PlateOf(plate), o, /*dead_after_s=*/0.2);
  SensorSetSamples got;
  while (source.bench()->now_s() < 3.0) source.Read(1.0, &got);
  ASSERT_FALSE(got.per_sensor[1].empty());
  EXPECT_LT(got.per_sensor[1].back().t_s, 1.0);  // nothing after its death
  EXPECT_GE(got.per_sensor[0].back().t_s, 2.9);
  EXPECT_GE(got.per_sensor[2].back().t_s, 2.9);
  // Dead by the wall clock: the others keep delivering, board 2 does not.
  for (int i = 0; i < 40 && source.status(1).link != LinkState::kDead; ++i) {
    usleep(10000);
    source.Read(0.0, &got);
  }
  EXPECT_EQ(source.status(1).link, LinkState::kDead);
  EXPECT_EQ(source.status(0).link, LinkState::kUp);
  EXPECT_EQ(source.status(2).link, LinkState::kUp);
}

// Standard deviation of |f| over the samples: motion shows as scatter far above the noise.
double ScatterMps2(const FixtureSimSource& source, std::size_t board,
                   const std::vector<Sample>& samples) {
  const Eigen::Vector3d mean = MeanMps2(source, board, samples);
  double sum2 = 0.0;
  for (const Sample& s : samples)
    sum2 += (source.truth(board).Calibrate(s.raw_counts) - mean).squaredNorm();
  return std::sqrt(sum2 / static_cast<double>(samples.size()));
}

TEST(FixtureSimSource, ALooseBoardGoesOnMovingAfterThePlateSettledThenSitsTilted) {
  sim::BenchFixture plate = sim::RowOfBoards(2);
  plate.boards[1].fault = sim::BoardFault::kLoose;
  plate.boards[1].loose_deg = 4.0;
  FixtureSimSource source(PlateOf(plate), Fast());
  source.bench()->PlaceStatic(Eigen::Vector3d::UnitY(), 0.0);
  const double t0 = source.bench()->now_s();
  const SensorSetSamples early = Between(source, t0 + 0.6, t0 + 1.6);  // plate settled at 0.5 s
  // The white noise alone: about 0.08 m/s^2 (1.5 counts per axis at 35 counts per m/s^2).
  const double resting = ScatterMps2(source, 0, early.per_sensor[0]);
  EXPECT_LT(resting, 0.1);
  EXPECT_GT(ScatterMps2(source, 1, early.per_sensor[1]), 1.5 * resting);
  const SensorSetSamples late = Between(source, t0 + 20.0, t0 + 22.0);
  EXPECT_LT(ScatterMps2(source, 1, late.per_sensor[1]), 1.1 * resting);
  // Its tilt on the plate: up is off its +y by the tilt drawn, which the bench reports.
  const Eigen::Vector3d up_board =
      source.mounted_to_plate(1).transpose() * Eigen::Vector3d::UnitY();
  EXPECT_NEAR(MeanMps2(source, 1, late.per_sensor[1]).normalized().dot(up_board), 1.0, 2e-4);
  EXPECT_LT(up_board.y(), 0.99999);
}

TEST(FixtureSimSource, RefusesAScenarioWithoutAFixture) {
  EXPECT_THROW(FixtureSimSource(sim::DefaultScenario(), Fast()), Error);
}

std::string TempFile(const std::string& text) {
  char path[] = "/tmp/sensor_set_XXXXXX";
  const int fd = mkstemp(path);
  close(fd);
  std::ofstream(path) << text;
  return path;
}

TEST(ColumnsSensorSet, EachSensorsColumnsOfOneLineAndItsOwnMalformedLines) {
  const std::string path = TempFile(
      "0.00 10 20 30 100 200 300\n"
      "0.01 11 21 31 101 2x1 301\n"
      "0.02 12 22 32 102 202 302\n");
  SourceOptions options;
  SensorSetRequest request;
  request.columns = "t,ax,ay,az,ax,ay,az";
  auto set = OpenSensorSet("file:" + path, options, request);
  ASSERT_EQ(set->sensor_count(), 2u);
  EXPECT_EQ(set->fixture().sensors[1].serial, "S02");
  SensorSetSamples got;
  for (int i = 0; i < 10 && set->status(0).link != LinkState::kEnded; ++i) set->Read(0.5, &got);
  ASSERT_EQ(got.per_sensor[0].size(), 3u);
  ASSERT_EQ(got.per_sensor[1].size(), 2u);  // its field '2x1' on the second line
  EXPECT_EQ(got.per_sensor[0][1].raw_counts, Eigen::Vector3d(11, 21, 31));
  EXPECT_EQ(got.per_sensor[1][1].raw_counts, Eigen::Vector3d(102, 202, 302));
  EXPECT_DOUBLE_EQ(got.per_sensor[1][1].t_s, 0.02);
  EXPECT_EQ(set->status(0).malformed_lines, 0);
  EXPECT_EQ(set->status(1).malformed_lines, 1);
  EXPECT_NE(set->status(1).last_malformed.find("2x1"), std::string::npos);
  EXPECT_EQ(set->status(1).link, LinkState::kEnded);
  unlink(path.c_str());
}

TEST(ColumnsSensorSet, TheFixturesSerialsAndCountsMustAgree) {
  const std::string path = TempFile("0 1 2 3 4 5 6\n");
  SourceOptions options;
  SensorSetRequest request;
  request.columns = "t,ax,ay,az,ax,ay,az";
  request.sensors = 3;
  EXPECT_THROW(OpenSensorSet("file:" + path, options, request), Error);
  request.sensors = 0;
  request.fixture = Fixture{};
  request.fixture->sensors.resize(2);
  request.fixture->sensors[0].serial = "A7";
  request.fixture->sensors[1].serial = "B9";
  auto set = OpenSensorSet("file:" + path, options, request);
  EXPECT_EQ(set->fixture().sensors[1].serial, "B9");
  SensorSetRequest no_columns;
  no_columns.sensors = 2;
  EXPECT_THROW(OpenSensorSet("file:" + path, options, no_columns), Error);
  unlink(path.c_str());
}

TEST(LinkedSensorSet, OneFilePerSensorFromTheFixture) {
  const std::string a = TempFile("0 1 2 3\n0.01 1 2 3\n");
  const std::string b = TempFile("0 7 8 9\n");
  SensorSetRequest request;
  request.fixture = Fixture{};
  request.fixture->sensors.resize(2);
  request.fixture->sensors[0] = {"A", Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), "file:" + a};
  request.fixture->sensors[1] = {"B", Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), "file:" + b};
  auto set = OpenSensorSet("sim", SourceOptions{}, request);
  SensorSetSamples got;
  for (int i = 0; i < 10; ++i) set->Read(0.2, &got);
  EXPECT_EQ(got.per_sensor[0].size(), 2u);
  ASSERT_EQ(got.per_sensor[1].size(), 1u);
  EXPECT_EQ(got.per_sensor[1][0].raw_counts, Eigen::Vector3d(7, 8, 9));
  unlink(a.c_str());
  unlink(b.c_str());
}

TEST(OpenSensorSet, SimWithSensorsNIsARowOfBoards) {
  SourceOptions options;
  options.sim = Fast();
  SensorSetRequest request;
  request.sensors = 8;
  auto set = OpenSensorSet("sim", options, request);
  EXPECT_EQ(set->sensor_count(), 8u);
  ASSERT_NE(set->bench(), nullptr);
  SensorSetSamples got;
  set->Read(1.0, &got);
  for (const auto& samples : got.per_sensor) EXPECT_FALSE(samples.empty());
}

}  // namespace
}  // namespace accelcal::sensor_set_source_test
