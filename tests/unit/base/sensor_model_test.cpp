#include "accelcal/base/sensor_model.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace accelcal {
namespace {

SensorModel Example() {
  SensorModel m;
  m.bias_counts = {2048.0, 2010.0, 2100.0};
  m.scale_counts_per_mps2 = {34.8, 35.5, 33.9};
  m.a_yz_rad = 0.004;
  m.a_zy_rad = -0.006;
  m.a_zx_rad = 0.002;
  return m;
}

TEST(SensorModel, MisalignmentHasTheSeedsSigns) {
  const Eigen::Matrix3d t = Example().Misalignment();
  EXPECT_DOUBLE_EQ(t(0, 1), -0.004);  // -a_yz
  EXPECT_DOUBLE_EQ(t(0, 2), -0.006);  // +a_zy
  EXPECT_DOUBLE_EQ(t(1, 2), -0.002);  // -a_zx
  EXPECT_DOUBLE_EQ(t(1, 0), 0.0);
  EXPECT_DOUBLE_EQ(t(2, 0), 0.0);
  EXPECT_DOUBLE_EQ(t(2, 1), 0.0);
  EXPECT_DOUBLE_EQ(t.diagonal().sum(), 3.0);
}

TEST(SensorModel, CalibrateInvertsRaw) {
  const SensorModel m = Example();
  const Eigen::Vector3d f(1.5, -9.7, 0.3);
  const Eigen::Vector3d raw = m.Raw(f);
  EXPECT_LT((m.Calibrate(raw) - f).norm(), 1e-12);
}

TEST(SensorModel, RawFollowsTheForwardEquation) {
  // raw = K a^a + b with a^p = T a^a: check against an explicit inverse of T.
  const SensorModel m = Example();
  const Eigen::Vector3d f(0.2, 0.1, 9.8);
  const Eigen::Vector3d a_a = m.Misalignment().inverse() * f;
  const Eigen::Vector3d expected = m.scale_counts_per_mps2.cwiseProduct(a_a) + m.bias_counts;
  EXPECT_LT((m.Raw(f) - expected).norm(), 1e-9);
}

TEST(SensorModel, VectorRoundTripAndValidation) {
  const SensorModel m = Example();
  const SensorModel back = SensorModel::FromVector(m.ToVector());
  EXPECT_EQ(back.ToVector(), m.ToVector());
  EXPECT_TRUE(m.Validate().empty());
  SensorModel bad = m;
  bad.scale_counts_per_mps2.y() = -1.0;
  EXPECT_NE(bad.Validate().find("scale_y"), std::string::npos);
  bad = m;
  bad.a_zx_rad = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(bad.Validate().find("a_zx"), std::string::npos);
}

}  // namespace
}  // namespace accelcal
