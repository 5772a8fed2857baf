// Leveling by reversal on a tilted table with a sensor whose bias the rough model gets wrong:
// one reading is fooled by the bias error, the reversal is not.
#include "accelcal/app/wizard/leveling.h"

#include <cmath>

#include <gtest/gtest.h>

namespace accelcal::leveling_test {
namespace {

constexpr double kG = 9.80665;

SensorModel Truth() {
  SensorModel m;
  m.bias_counts = {2048, 2048, 2048};
  m.scale_counts_per_mps2 = {34.8, 34.8, 34.8};
  return m;
}

// The up direction in the table's frame for a table tilted by small angles (rad).
Eigen::Vector3d Up(double about_x_rad, double about_y_rad) {
  return Eigen::Vector3d(std::sin(about_y_rad), -std::sin(about_x_rad), 1.0).normalized();
}

TEST(Leveling, ReversalRemovesTheSensorOffsetThatFoolsOneReading) {
  const SensorModel truth = Truth();
  SensorModel rough = truth;
  rough.bias_counts += Eigen::Vector3d(25.0, -18.0, 0.0);  // ~4 deg worth of offset
  const Eigen::Vector3d up = Up(0.02, -0.015);
  const Eigen::Vector3d first = truth.Raw(kG * up);
  // Turned 180 deg about the vertical: x and y of the table's tilt change sign in the sensor.
  const Eigen::Vector3d turned = truth.Raw(kG * Eigen::Vector3d(-up.x(), -up.y(), up.z()));

  const Eigen::Vector2d true_tilt = ApparentTiltDeg(first, truth);  // what a perfect sensor sees
  const Eigen::Vector2d fooled = ApparentTiltDeg(first, rough);
  const Eigen::Vector2d reversal = ReversalTiltDeg(first, turned, rough);
  EXPECT_GT((fooled - true_tilt).norm(), 1.0);         // one reading is off by degrees
  EXPECT_LT((reversal - true_tilt).norm(), 0.01);      // the reversal is not
  EXPECT_NEAR(true_tilt.norm(), std::hypot(0.02, 0.015) * 180 / M_PI, 0.01);
}

TEST(Leveling, AdviceSaysWhatToDoUntilWithinTolerance) {
  EXPECT_EQ(LevelingAdvice(Eigen::Vector2d(0.05, -0.08), 0.1), "");
  const std::string advice = LevelingAdvice(Eigen::Vector2d(1.9, -0.4), 0.1);
  EXPECT_FALSE(advice.empty());
  EXPECT_TRUE(advice.find("raise") != std::string::npos || advice.find("lower") != std::string::npos) << advice;
  EXPECT_NE(advice.find("1.9"), std::string::npos) << advice;
  EXPECT_NE(advice.find("0.4"), std::string::npos) << advice;
  // Only the axis beyond tolerance is mentioned.
  const std::string one = LevelingAdvice(Eigen::Vector2d(0.02, 2.5), 0.1);
  EXPECT_NE(one.find("2.5"), std::string::npos) << one;
  EXPECT_EQ(one.find("0.0"), std::string::npos) << one;
}

}  // namespace
}  // namespace accelcal::leveling_test
