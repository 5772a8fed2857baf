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

// Issue 15: "0,12" and "2 Hz" were not understood.
TEST(QuantityInputTest, DecimalCommaAndHertz) {
  EXPECT_DOUBLE_EQ(ParseRadius("0,12").value, 0.12);
  EXPECT_DOUBLE_EQ(ParseRadius("12,5 cm").value, 0.125);
  EXPECT_DOUBLE_EQ(ParseRpm("2 Hz").value, 120.0);
  EXPECT_DOUBLE_EQ(ParseRpm("2Hz").value, 120.0);
  EXPECT_DOUBLE_EQ(ParseRpm("1,5 rps").value, 90.0);
  // Two commas, or a comma beside a point, are not a decimal comma: refused, never misread.
  EXPECT_FALSE(ParseRadius("0,1,2").ok());
  EXPECT_FALSE(ParseRadius("1.0,5 cm").ok());
  // "1,200" may be 1.2 or 1200 (a thousands separator): refused, never guessed.
  EXPECT_EQ(ParseRpm("1,200").error, "'1,200' could be 1.200 or 1200: type it without the comma, "
                                     "or with a point");
  EXPECT_FALSE(ParseRadius("1,500 mm").ok());
  EXPECT_DOUBLE_EQ(ParseRadius("0,125").value, 0.125);  // a leading 0 is never a thousands group
  EXPECT_DOUBLE_EQ(ParseRpm("1,20 rps").value, 72.0);
}

// Issue 15: "300 rpm" at the radius got "unknown unit 'rpm' for a radius".
TEST(QuantityInputTest, AUnitNamesItsField) {
  EXPECT_EQ(FieldOfUnit("300 rpm"), TurntableField::kSpeed);
  EXPECT_EQ(FieldOfUnit("2 Hz"), TurntableField::kSpeed);
  EXPECT_EQ(FieldOfUnit("12.57 rad/s"), TurntableField::kSpeed);
  EXPECT_EQ(FieldOfUnit("5 cm"), TurntableField::kRadius);
  EXPECT_EQ(FieldOfUnit("0,12 m"), TurntableField::kRadius);
  EXPECT_EQ(FieldOfUnit("120"), TurntableField::kNone);
  EXPECT_EQ(FieldOfUnit("12 in"), TurntableField::kNone);
  EXPECT_EQ(FieldOfUnit("fast"), TurntableField::kNone);
  const std::string at_radius = ParseRadius("300 rpm").error;
  EXPECT_EQ(at_radius.find("unknown unit"), std::string::npos) << at_radius;
  EXPECT_NE(at_radius.find("speed field"), std::string::npos) << at_radius;
  EXPECT_NE(ParseRpm("5 cm").error.find("radius field"), std::string::npos);
}

TEST(QuantityInputTest, BlankIsBlank) {
  EXPECT_TRUE(IsBlank(""));
  EXPECT_TRUE(IsBlank("   \t "));
  EXPECT_FALSE(IsBlank(" 1 "));
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
