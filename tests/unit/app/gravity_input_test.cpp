// The local gravity as typed at the wizard's welcome (or given with --gravity).
#include "accelcal/app/wizard/gravity_input.h"

#include <cmath>

#include <gtest/gtest.h>

#include "test_support.h"

namespace accelcal::gravity_input_test {
namespace {

using testing::Contains;

TEST(GravityInput, AMeasuredValueWithItsUncertainty) {
  const GravityAnswer a = ParseGravityAnswer("9.78030 +- 0.00002");
  ASSERT_TRUE(a.ok()) << a.error;
  EXPECT_EQ(a.gravity.source, GravitySpec::Source::kGiven);
  EXPECT_DOUBLE_EQ(a.gravity.gravity_mps2, 9.7803);
  EXPECT_DOUBLE_EQ(a.gravity.sigma_mps2, 0.00002);
  for (const char* text : {"9.78030 m/s^2 +- 0.00002 m/s^2", "9.78030±0.00002", "9.78030+-0.00002",
                           "9.78030 +/- 0.00002"}) {
    const GravityAnswer b = ParseGravityAnswer(text);
    ASSERT_TRUE(b.ok()) << text << ": " << b.error;
    EXPECT_DOUBLE_EQ(b.gravity.sigma_mps2, 0.00002) << text;
  }
}

TEST(GravityInput, WithoutAnUncertaintyTheResolutionTypedIsIt) {
  // Half a unit of the last digit, rectangular: 0.00005 / sqrt(3).
  const GravityAnswer a = ParseGravityAnswer("9.7803");
  ASSERT_TRUE(a.ok()) << a.error;
  EXPECT_NEAR(a.gravity.sigma_mps2, 0.00005 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(ParseGravityAnswer("9.78").gravity.sigma_mps2, 0.005 / std::sqrt(3.0), 1e-12);
}

TEST(GravityInput, APlaceGivesWgs84NormalGravity) {
  const GravityAnswer a = ParseGravityAnswer("lat -34.9 alt 43");
  ASSERT_TRUE(a.ok()) << a.error;
  EXPECT_EQ(a.gravity.source, GravitySpec::Source::kWgs84);
  EXPECT_DOUBLE_EQ(a.gravity.gravity_mps2, NormalGravityWgs84Mps2(-34.9, 43.0));
  EXPECT_NEAR(a.gravity.sigma_mps2, 0.0005, 1e-6);
  const GravityAnswer b = ParseGravityAnswer("Latitude -34.9 deg, altitude 43 m");
  ASSERT_TRUE(b.ok()) << b.error;
  EXPECT_DOUBLE_EQ(b.gravity.gravity_mps2, a.gravity.gravity_mps2);
  EXPECT_DOUBLE_EQ(ParseGravityAnswer("lat 0").gravity.gravity_mps2, NormalGravityWgs84Mps2(0.0, 0.0));
}

TEST(GravityInput, StandardIsSaidExplicitly) {
  const GravityAnswer a = ParseGravityAnswer("standard");
  ASSERT_TRUE(a.ok());
  EXPECT_TRUE(a.gravity.is_standard());
  EXPECT_NEAR(a.gravity.sigma_mps2, 0.04 / std::sqrt(3.0), 1e-12);
}

TEST(GravityInput, AnythingElseIsRefusedWithTheReason) {
  EXPECT_TRUE(Contains(ParseGravityAnswer("").error, "no gravity given"));
  EXPECT_TRUE(Contains(ParseGravityAnswer("978.03").error, "Gal"));
  EXPECT_TRUE(Contains(ParseGravityAnswer("0.978").error, "plausible"));
  EXPECT_TRUE(Contains(ParseGravityAnswer("9.78 +-").error, "standard uncertainty"));
  EXPECT_TRUE(Contains(ParseGravityAnswer("9.78 +- 0.5").error, "uncertainty"));
  EXPECT_TRUE(Contains(ParseGravityAnswer("lat 120").error, "latitude"));
  EXPECT_TRUE(Contains(ParseGravityAnswer("alt 40").error, "latitude"));
  EXPECT_TRUE(Contains(ParseGravityAnswer("nine point eight").error, "not a number"));
  EXPECT_TRUE(Contains(ParseGravityAnswer("standard 9.8").error, "standard"));
}

TEST(GravityInput, WhatIsRecordedReadsBackTheSame) {
  for (const GravitySpec& g : {GravitySpec::Standard(), GravitySpec::Given(9.78031, 0.00002),
                               GravitySpec::FromLocation(-34.9, 43.0)}) {
    const GravityAnswer back = ParseGravityAnswer(GravityAnswerText(g));
    ASSERT_TRUE(back.ok()) << GravityAnswerText(g) << ": " << back.error;
    EXPECT_EQ(back.gravity.source, g.source);
    EXPECT_DOUBLE_EQ(back.gravity.gravity_mps2, g.gravity_mps2);
    EXPECT_DOUBLE_EQ(back.gravity.sigma_mps2, g.sigma_mps2);
  }
}

}  // namespace
}  // namespace accelcal::gravity_input_test
