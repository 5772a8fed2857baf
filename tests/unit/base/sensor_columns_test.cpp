// --columns of a line with several sensors: the k-th ax, ay, az are sensor k's.
#include "accelcal/base/sensor_columns.h"

#include <gtest/gtest.h>

namespace accelcal::sensor_columns_test {
namespace {

std::string Names(const std::vector<NamedColumn>& columns) {
  std::string text;
  for (const NamedColumn& c : columns) text += (text.empty() ? "" : ",") + ColumnListName(c);
  return text;
}

TEST(SplitSensorColumns, TheKthGroupIsSensorK) {
  std::string error;
  const auto sensors = SplitSensorColumns("t_ms, ax,ay,az, -, ax,ay,az, temp_c", &error);
  ASSERT_EQ(sensors.size(), 2u) << error;
  EXPECT_EQ(Names(sensors[0]), "t_ms,ax,ay,az,-,-,-,-,temp_c");
  EXPECT_EQ(Names(sensors[1]), "t_ms,-,-,-,-,ax,ay,az,temp_c");
}

TEST(SplitSensorColumns, ATemperaturePerSensorIsItsOwn) {
  std::string error;
  const auto sensors = SplitSensorColumns("t,ax,ay,az,temp_c,ax,ay,az,temp_c", &error);
  ASSERT_EQ(sensors.size(), 2u) << error;
  EXPECT_EQ(Names(sensors[1]), "t,-,-,-,-,ax,ay,az,temp_c");
}

TEST(SplitSensorColumns, OneSensorIsTheOrdinaryList) {
  std::string error;
  const auto sensors = SplitSensorColumns("t,az,ay,ax", &error);
  ASSERT_EQ(sensors.size(), 1u) << error;
  EXPECT_EQ(Names(sensors[0]), "t,az,ay,ax");
}

TEST(SplitSensorColumns, RefusesUnevenGroupsAndSaysWhy) {
  std::string error;
  EXPECT_TRUE(SplitSensorColumns("t,ax,ay,az,ax,ay", &error).empty());
  EXPECT_NE(error.find("2, 2 and 1"), std::string::npos) << error;
  EXPECT_TRUE(SplitSensorColumns("t,ax,ay,az,ax,ay,az,t", &error).empty());
  EXPECT_NE(error.find("t is named twice"), std::string::npos) << error;
  EXPECT_TRUE(SplitSensorColumns("t,ax,ay,az,ax,ay,az,ax,ay,az,temp_c,temp_c", &error).empty());
  EXPECT_NE(error.find("temp_c named 2 times"), std::string::npos) << error;
  EXPECT_TRUE(SplitSensorColumns("t,ax,ay,az,gx", &error).empty());
  EXPECT_NE(error.find("unknown column 'gx'"), std::string::npos) << error;
}

}  // namespace
}  // namespace accelcal::sensor_columns_test
