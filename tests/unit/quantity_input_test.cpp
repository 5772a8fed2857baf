// Radius and speed as the operator types them, and the plan checked against the range.
#include <gtest/gtest.h>

#include "accelcal/app/wizard/quantity_input.h"

namespace accelcal {
namespace {

TEST(QuantityInputTest, RadiusInEveryUnit) {
  EXPECT_DOUBLE_EQ(ParseRadius("120 mm").value, 0.12);
  EXPECT_DOUBLE_EQ(ParseRadius("12 cm").value, 0.12);
  EXPECT_DOUBLE_EQ(ParseRadius("0.12 m").value, 0.12);
  EXPECT_DOUBLE_EQ(ParseRadius("0.12").value, 0.12);
  EXPECT_DOUBLE_EQ(ParseRadius("  120mm ").value, 0.12);
  EXPECT_DOUBLE_EQ(ParseRadius("12 CM").value, 0.12);
}

TEST(QuantityInputTest, AbsurdRadiiAreRefusedWithASuggestion) {
  EXPECT_EQ(ParseRadius("12 m").error,
            "12 m is not a plausible turntable radius: did you mean 12 cm?");
  EXPECT_NE(ParseRadius("120").error.find("did you mean 120 mm?"), std::string::npos);
  EXPECT_NE(ParseRadius("2 mm").error.find("not a plausible"), std::string::npos);
  EXPECT_NE(ParseRadius("5000 m").error.find("expected"), std::string::npos);
  EXPECT_NE(ParseRadius("-3 cm").error.find("not a plausible"), std::string::npos);
  EXPECT_NE(ParseRadius("abc").error.find("not a radius"), std::string::npos);
  EXPECT_NE(ParseRadius("12 in").error.find("unknown unit 'in'"), std::string::npos);
  EXPECT_FALSE(ParseRadius("").ok());
}

TEST(QuantityInputTest, SpeedInEveryUnit) {
  EXPECT_DOUBLE_EQ(ParseRpm("120").value, 120.0);
  EXPECT_DOUBLE_EQ(ParseRpm("120 rpm").value, 120.0);
  EXPECT_DOUBLE_EQ(ParseRpm("2 rps").value, 120.0);
  EXPECT_NEAR(ParseRpm("12.57 rad/s").value, 120.03, 0.01);
}

TEST(QuantityInputTest, AbsurdSpeedsAreRefused) {
  EXPECT_NE(ParseRpm("5000").error.find("not a plausible turntable speed"), std::string::npos);
  EXPECT_NE(ParseRpm("0.5").error.find("not a plausible"), std::string::npos);
  EXPECT_NE(ParseRpm("fast").error.find("not a speed"), std::string::npos);
  EXPECT_NE(ParseRpm("120 mph").error.find("unknown unit"), std::string::npos);
}

TEST(QuantityInputTest, PlanBeyondTheRangeIsRefusedBeforeTheTableSpins) {
  SensorModel nominal;
  nominal.scale_counts_per_mps2 = Eigen::Vector3d::Constant(34.8);
  nominal.bias_counts = Eigen::Vector3d::Constant(2048);
  TurntableSetup setup;
  setup.radius_m = 0.15;
  setup.rpm = 120;
  const TurntableStabilityOptions options;
  EXPECT_EQ(CheckTurntableAgainstRange(setup, 6.0, nominal, {0, 4095}, options), "");
  setup.rpm = 300;
  setup.radius_m = 1.0;
  EXPECT_NE(CheckTurntableAgainstRange(setup, 6.0, nominal, {0, 4095}, options).find("range"),
            std::string::npos);
  // Within the ADC but beyond a smaller stated range.
  setup.rpm = 120;
  setup.radius_m = 0.15;
  EXPECT_NE(CheckTurntableAgainstRange(setup, 2.0, nominal, {0, 4095}, options).find("+-2 g"),
            std::string::npos);
}

}  // namespace
}  // namespace accelcal
