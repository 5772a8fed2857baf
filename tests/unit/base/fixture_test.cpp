// The fixture's geometry, checked on cases worked by hand (a board turned on the plate, a plate
// on its side on the turntable), not by the formulas fixture.cpp uses.
#include "accelcal/base/fixture.h"

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include "test_support.h"

namespace accelcal::fixture_test {
namespace {

using testing::Contains;

FixtureSensor Turned(SensorAxis x, SensorAxis y, Eigen::Vector3d offset_m = Eigen::Vector3d::Zero()) {
  return FixtureSensor{"SN", SensorToPlate(x, y), offset_m, {}};
}

TEST(Fixture, SquareSensorSeesThePlatesAxes) {
  const FixtureSensor s = Turned(SensorAxis::kPlusX, SensorAxis::kPlusY);
  EXPECT_EQ(SensorAxisOf(s, SensorAxis::kMinusY), SensorAxis::kMinusY);
  EXPECT_TRUE(SensorDirection(s, Eigen::Vector3d(0.6, 0, 0.8)).isApprox(Eigen::Vector3d(0.6, 0, 0.8)));
}

// A board turned 90 degrees about the plate's z: its x along the plate's +y, its y along -x.
// The plate's +x is then the board's -y; the plate's +y its +x; z stays.
TEST(Fixture, BoardTurnedAboutZ) {
  const FixtureSensor s = Turned(SensorAxis::kPlusY, SensorAxis::kMinusX);
  EXPECT_EQ(SensorAxisOf(s, SensorAxis::kPlusX), SensorAxis::kMinusY);
  EXPECT_EQ(SensorAxisOf(s, SensorAxis::kPlusY), SensorAxis::kPlusX);
  EXPECT_EQ(SensorAxisOf(s, SensorAxis::kMinusZ), SensorAxis::kMinusZ);
  EXPECT_TRUE(SensorDirection(s, Eigen::Vector3d(1, 2, 3)).isApprox(Eigen::Vector3d(2, -1, 3)));
}

// A board upside down (turned 180 degrees about the plate's x): x stays, y and z flip.
TEST(Fixture, BoardUpsideDown) {
  const FixtureSensor s = Turned(SensorAxis::kPlusX, SensorAxis::kMinusY);
  EXPECT_EQ(SensorAxisOf(s, SensorAxis::kPlusZ), SensorAxis::kMinusZ);
  EXPECT_TRUE(SensorDirection(s, Eigen::Vector3d(0, 0, 1)).isApprox(Eigen::Vector3d(0, 0, -1)));
}

TEST(Fixture, AxesMustBePerpendicular) {
  EXPECT_THROW(SensorToPlate(SensorAxis::kPlusX, SensorAxis::kMinusX), Error);
}

// Plate flat (radial +x, up +z) with its reference 0.1 m out: a sensor 0.02 m further out and
// 0.03 m sideways is at sqrt(0.12^2 + 0.03^2); its height (0.5 m) changes nothing.
TEST(Fixture, RadiusOfASensorOnAFlatPlate) {
  const FixtureSensor s = Turned(SensorAxis::kPlusX, SensorAxis::kPlusY, {0.02, 0.03, 0.5});
  EXPECT_NEAR(SensorRadiusM(s, 0.1, SensorAxis::kPlusX, SensorAxis::kPlusZ),
              std::sqrt(0.12 * 0.12 + 0.03 * 0.03), 1e-15);
  // The same sensor on the plate turned half a turn (radial -x): 0.02 m nearer the axis.
  EXPECT_NEAR(SensorRadiusM(s, 0.1, SensorAxis::kMinusX, SensorAxis::kPlusZ),
              std::sqrt(0.08 * 0.08 + 0.03 * 0.03), 1e-15);
}

// Plate on its side: its +z outward, its -x up. Its x is then along the spin axis (down), so the
// offset's x changes nothing; its z adds to the radius; its y stays sideways.
TEST(Fixture, RadiusOfASensorOnAPlateOnItsSide) {
  const FixtureSensor s = Turned(SensorAxis::kPlusX, SensorAxis::kPlusY, {0.02, 0.03, 0.04});
  EXPECT_NEAR(SensorRadiusM(s, 0.1, SensorAxis::kPlusZ, SensorAxis::kMinusX),
              std::sqrt(0.14 * 0.14 + 0.03 * 0.03), 1e-15);
}

// A plate centred on the axis: each sensor's radius is its horizontal distance from it.
TEST(Fixture, PlateCentredOnTheAxis) {
  const FixtureSensor s = Turned(SensorAxis::kPlusY, SensorAxis::kMinusX, {-0.03, 0.04, 0.0});
  EXPECT_NEAR(SensorRadiusM(s, 0.0, SensorAxis::kPlusX, SensorAxis::kPlusZ), 0.05, 1e-15);
}

TEST(Fixture, OneSensorSessionIsASquareSensorAtTheReference) {
  const Fixture f = SingleSensorFixture("A1");
  EXPECT_EQ(f.Validate(), "");
  ASSERT_EQ(f.sensors.size(), 1u);
  EXPECT_EQ(f.sensors[0].serial, "A1");
  EXPECT_NEAR(SensorRadiusM(f.sensors[0], 0.2, SensorAxis::kPlusY, SensorAxis::kMinusX), 0.2, 1e-15);
}

TEST(Fixture, ValidateNamesTheSensor) {
  Fixture f;
  EXPECT_TRUE(Contains(f.Validate(), "no sensor"));
  f.sensors = {FixtureSensor{"A", Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), {}},
               FixtureSensor{"A", Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), {}}};
  EXPECT_TRUE(Contains(f.Validate(), "sensor 2: serial 'A'")) << f.Validate();
  f.sensors[1].serial = "";
  EXPECT_TRUE(Contains(f.Validate(), "sensor 2 has no serial")) << f.Validate();
  f.sensors[1].serial = "B";
  f.sensors[1].sensor_to_plate = -Eigen::Matrix3d::Identity();  // a mirror: no board is one
  EXPECT_TRUE(Contains(f.Validate(), "sensor 2: its rotation")) << f.Validate();
  f.sensors[1].sensor_to_plate = Eigen::Matrix3d::Identity();
  f.sensors[1].offset_m.x() = std::nan("");
  EXPECT_TRUE(Contains(f.Validate(), "sensor 2: its offset")) << f.Validate();
  f.sensors[1].offset_m.x() = 0.01;
  EXPECT_EQ(f.Validate(), "");
  f.placement_u_rad = -0.001;
  EXPECT_TRUE(Contains(f.Validate(), "placement uncertainty")) << f.Validate();
  f.placement_u_rad = std::nan("");  // not stated: a plate placed by hand
  EXPECT_EQ(f.Validate(), "");
  EXPECT_NEAR(f.PlacementURad(), 0.5 * M_PI / 180.0, 1e-15);
}

// The spread of a board's turntable radius over many placements of the plate, each a small
// random rotation (each component N(0, u)) about its reference point, worked out from the board's
// position on the table directly; SensorRadiusPerTurnM times u must give it.
double SimulatedRadiusStd(const Eigen::Vector3d& offset_table_m, double plate_radius_m, double u_rad) {
  std::mt19937_64 rng(17);
  std::normal_distribution<double> angle(0.0, u_rad);
  double sum = 0.0, sum2 = 0.0;
  constexpr int kDraws = 40000;
  for (int i = 0; i < kDraws; ++i) {
    const Eigen::Vector3d v(angle(rng), angle(rng), angle(rng));
    const Eigen::Vector3d moved = Eigen::AngleAxisd(v.norm(), v.normalized()) * offset_table_m;
    const double r = std::hypot(plate_radius_m + moved.x(), moved.y());
    sum += r;
    sum2 += r * r;
  }
  const double mean = sum / kDraws;
  return std::sqrt(sum2 / kDraws - mean * mean);
}

TEST(Fixture, RadiusPerTurnIsTheSpreadOfThePlatesPlacements) {
  const double u_rad = 0.1 * M_PI / 180.0;
  // Radial +x, up +z: the plate's axes are the table's.
  const FixtureSensor flat = Turned(SensorAxis::kPlusX, SensorAxis::kPlusY, {0.05, 0.08, 0.03});
  EXPECT_NEAR(u_rad * SensorRadiusPerTurnM(flat, 0.10, SensorAxis::kPlusX, SensorAxis::kPlusZ),
              SimulatedRadiusStd({0.05, 0.08, 0.03}, 0.10, u_rad), 0.03 * SimulatedRadiusStd({0.05, 0.08, 0.03}, 0.10, u_rad));
  // The plate on its side: its +z outward, its +x up. On the table: radial = plate z,
  // tangential = up x radial = x cross z = -y, up = plate x.
  const Eigen::Vector3d on_table(0.03, -0.08, 0.05);
  EXPECT_NEAR(u_rad * SensorRadiusPerTurnM(flat, 0.15, SensorAxis::kPlusZ, SensorAxis::kPlusX),
              SimulatedRadiusStd(on_table, 0.15, u_rad), 0.03 * SimulatedRadiusStd(on_table, 0.15, u_rad));
  // A board on the radial line through the reference, level with it: a turn moves it along the
  // circle, its radius only at second order.
  const FixtureSensor radial = Turned(SensorAxis::kPlusX, SensorAxis::kPlusY, {0.06, 0.0, 0.0});
  EXPECT_NEAR(SensorRadiusPerTurnM(radial, 0.10, SensorAxis::kPlusX, SensorAxis::kPlusZ), 0.0, 1e-12);
  // At the reference point: nothing.
  EXPECT_EQ(SensorRadiusPerTurnM(Turned(SensorAxis::kPlusX, SensorAxis::kPlusY), 0.10,
                                 SensorAxis::kPlusX, SensorAxis::kPlusZ), 0.0);
}

}  // namespace
}  // namespace accelcal::fixture_test
