// The fixture file (io/fixture_file.h): the shipped example read whole, and every mistake a
// person writing one makes refused at its line with the sensor named.
#include "accelcal/io/fixture_file.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "test_support.h"

#include "accelcal/base/error.h"

namespace accelcal::fixture_file_test {
namespace {

using testing::Contains;

InputError ParseFails(const std::string& text) {
  return testing::ExpectInputError([&] { ParseFixture(text, "fix.toml"); }, text);
}

TEST(FixtureFile, ReadsTheExamplePlate) {
  const Fixture f = LoadFixture(std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/fixture/plate_8.toml");
  EXPECT_EQ(f.name, "plate 8");
  ASSERT_EQ(f.sensors.size(), 8u);
  EXPECT_EQ(f.sensors[0].serial, "A0001");
  EXPECT_EQ(f.sensors[7].serial, "A0008");
  EXPECT_TRUE(f.sensors[0].sensor_to_plate.isIdentity());
  EXPECT_TRUE(f.sensors[0].source.empty());
  // Board 3, a quarter turn: the plate's +x is its -y.
  EXPECT_EQ(SensorAxisOf(f.sensors[2], SensorAxis::kPlusX), SensorAxis::kMinusY);
  // Board 6, upside down: the plate's up is its -z.
  EXPECT_EQ(SensorAxisOf(f.sensors[5], SensorAxis::kPlusZ), SensorAxis::kMinusZ);
  // Board 2 at the reference point; board 1, 50 mm beside it along -x: at a 0.1 m radius with
  // the plate's +x outward, 0.05 m from the axis.
  EXPECT_TRUE(f.sensors[1].offset_m.isZero());
  EXPECT_NEAR(SensorRadiusM(f.sensors[0], 0.1, SensorAxis::kPlusX, SensorAxis::kPlusZ), 0.05, 1e-15);
}

TEST(FixtureFile, OneSensorWithItsOwnLink) {
  const Fixture f = ParseFixture("[[sensor]]\nserial = \"S1\"\nsource = \"tcp:bench:5000\"\n", "f");
  ASSERT_EQ(f.sensors.size(), 1u);
  EXPECT_EQ(f.name, "");
  EXPECT_EQ(f.sensors[0].source, "tcp:bench:5000");
  EXPECT_TRUE(f.sensors[0].offset_m.isZero());
}

TEST(FixtureFile, RefusesWhatIsWrongWhereItIs) {
  EXPECT_TRUE(Contains(ParseFails("name = \"empty\"\n").what(), "no [[sensor]]"));
  const InputError repeated =
      ParseFails("[[sensor]]\nserial = \"S1\"\n\n[[sensor]]\nserial = \"S1\"\n");
  EXPECT_EQ(repeated.line(), 5);
  EXPECT_TRUE(Contains(repeated.what(), "sensor 2.serial: 'S1' is already another sensor's"))
      << repeated.what();
  EXPECT_TRUE(Contains(ParseFails("[[sensor]]\nx = \"+x\"\n").what(), "sensor 1.serial"));
  EXPECT_TRUE(Contains(ParseFails("[[sensor]]\nserial = \"a,b\"\n").what(), "without commas"));
  const InputError axis = ParseFails("[[sensor]]\nserial = \"S\"\nx = \"up\"\n");
  EXPECT_EQ(axis.line(), 3);
  EXPECT_TRUE(Contains(axis.what(), "got 'up'")) << axis.what();
  const InputError parallel = ParseFails("[[sensor]]\nserial = \"S\"\nx = \"+y\"\n");
  EXPECT_TRUE(Contains(parallel.what(), "sensor 1.x: the sensor's x (+y) and y (+y) must be "
                                        "perpendicular"))
      << parallel.what();
  EXPECT_TRUE(Contains(ParseFails("[[sensor]]\nserial = \"S\"\noffset_m = [0, nan, 0]\n").what(),
                       "finite"));
  EXPECT_TRUE(Contains(ParseFails("[[sensor]]\nserial = \"S\"\nrotation = 90\n").what(),
                       "rotation"));
  EXPECT_TRUE(Contains(ParseFails("plate = 1\n[[sensor]]\nserial = \"S\"\n").what(), "plate"));
}

TEST(FixtureFile, ThePlatesPlacementUncertaintyInDegrees) {
  const Fixture stated = ParseFixture("placement_u_deg = 0.1\n[[sensor]]\nserial = \"S1\"\n", "f");
  EXPECT_NEAR(stated.placement_u_rad, 0.1 * M_PI / 180.0, 1e-15);
  const Fixture unstated = ParseFixture("[[sensor]]\nserial = \"S1\"\n", "f");
  EXPECT_TRUE(std::isnan(unstated.placement_u_rad));
  const InputError negative = ParseFails("placement_u_deg = -0.1\n[[sensor]]\nserial = \"S\"\n");
  EXPECT_EQ(negative.line(), 1);
  EXPECT_TRUE(Contains(negative.what(), "placement_u_deg")) << negative.what();
}

TEST(FixtureFile, AMissingFileIsAnError) {
  EXPECT_THROW(LoadFixture("/nonexistent/fixture.toml"), Error);
}

}  // namespace
}  // namespace accelcal::fixture_file_test
