#include "accelcal/base/gravity.h"

#include <cmath>

#include <gtest/gtest.h>

namespace accelcal {
namespace {

// Reference values: WGS84 normal gravity on the ellipsoid at the equator and the poles are
// defining/derived constants (NIMA TR8350.2 table 3.3): 9.7803253359 and 9.8321849378 m/s^2.
TEST(Gravity, Wgs84AtEquatorAndPoles) {
  EXPECT_NEAR(NormalGravityWgs84Mps2(0.0, 0.0), 9.7803253359, 1e-9);
  EXPECT_NEAR(NormalGravityWgs84Mps2(90.0, 0.0), 9.8321849378, 1e-9);
  EXPECT_NEAR(NormalGravityWgs84Mps2(-90.0, 0.0), 9.8321849378, 1e-9);
}

TEST(Gravity, Wgs84FreeAirGradientIsAbout0_3086mGalPerMetre) {
  // The familiar free-air gradient: -0.3086 mGal/m = -3.086e-6 m/s^2 per metre at mid latitudes.
  const double dg = NormalGravityWgs84Mps2(45.0, 1000.0) - NormalGravityWgs84Mps2(45.0, 0.0);
  EXPECT_NEAR(dg / 1000.0, -3.086e-6, 0.01e-6);
}

TEST(Gravity, ValidateCatchesUnitMistakes) {
  EXPECT_TRUE(GravitySpec::Standard().Validate().empty());
  EXPECT_NE(GravitySpec::Given(0.980665).Validate(), "");     // in daN? in tens of g?
  EXPECT_NE(GravitySpec::Given(980.665).Validate(), "");      // in Gal
  EXPECT_NE(GravitySpec::FromLocation(120.0, 0.0).Validate(), "");
  EXPECT_NE(GravitySpec::FromLocation(45.0, 45000.0).Validate(), "");  // feet? km?
  EXPECT_TRUE(GravitySpec::FromLocation(-34.9, 43.0).Validate().empty());
}

TEST(Gravity, EachSourceCarriesItsStandardUncertainty) {
  // The standard value: Earth's surface spans about 9.76..9.84 m/s^2, rectangular around it.
  EXPECT_NEAR(GravitySpec::Standard().sigma_mps2, 0.04 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(GravitySpec::FromLocation(45.0, 100.0).sigma_mps2, 0.0005, 1e-6);
  EXPECT_DOUBLE_EQ(GravitySpec::Given(9.81, 0.0001).sigma_mps2, 0.0001);
  EXPECT_TRUE(std::isnan(GravitySpec::Given(9.81).sigma_mps2));  // not stated
  EXPECT_NE(GravitySpec::Given(9.81, -0.1).Validate(), "");
  EXPECT_NE(GravitySpec::Given(9.81, 0.5).Validate(), "");
  EXPECT_NE(GravitySpec::Given(9.7803, 0.00002).Describe().find("+- 0.00002"), std::string::npos);
  EXPECT_NE(GravitySpec::Standard().Describe().find("not the local value"), std::string::npos);
}

TEST(Gravity, DescribeNamesTheSource) {
  EXPECT_NE(GravitySpec::Standard().Describe().find("standard"), std::string::npos);
  EXPECT_NE(GravitySpec::Given(9.81744).Describe().find("9.81744"), std::string::npos);
  EXPECT_NE(GravitySpec::FromLocation(-34.9, 43.0).Describe().find("WGS84"), std::string::npos);
}

}  // namespace
}  // namespace accelcal
