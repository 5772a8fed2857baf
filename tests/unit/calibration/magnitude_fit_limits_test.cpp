// Issue 13 item 5: what a magnitude fit cannot see (docs/model.md, "The model"). On exact, noise-free
// captures of the seed's plan, written here from raw = K M f + b with M chosen by the test:
//  - a mounting rotation (M = T^-1 R) is invisible: the fit returns T, K and b exactly, |a^p| is
//    right, and the direction of a^p is off by the whole rotation;
//  - a lower-triangular misalignment (M = L^-1) is absorbed into magnitude-equivalent angles:
//    |a^p| is right for every direction (also ones the fit never saw), the fitted angles are not
//    L's, and directions are off by a small rotation.
#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "accelcal/calibration/fit/calibration_fit.h"

namespace accelcal::magnitude_fit_limits_test {
namespace {

constexpr double kG = 9.80665;
const Eigen::Vector3d kBias(2051.3, 2039.6, 2062.8);
const Eigen::Vector3d kScale(34.62, 35.07, 34.41);

// The specific forces of the seed's plan, platform frame: six faces, three corners with
// independent sign patterns, and turntable runs (x, y radial with z up; z radial with x up) at
// 0.05/0.10/0.15 m and 120 rpm.
std::vector<std::pair<Eigen::Vector3d, FitCapture>> Plan() {
  std::vector<std::pair<Eigen::Vector3d, FitCapture>> plan;
  auto add_static = [&](Eigen::Vector3d up) {
    FitCapture c;
    c.kind = CaptureKind::kStatic;
    plan.push_back({kG * up.normalized(), c});
  };
  for (int j = 0; j < 3; ++j)
    for (double s : {1.0, -1.0}) add_static(s * Eigen::Vector3d::Unit(j));
  add_static({1, 1, 1});
  add_static({1, 1, -1});
  add_static({1, -1, 1});
  const double w = 120.0 * 2.0 * M_PI / 60.0;
  const std::pair<int, int> mounts[] = {{0, 2}, {1, 2}, {2, 0}};  // radial axis, up axis
  for (const auto& [radial, up] : mounts)
    for (double r : {0.05, 0.10, 0.15}) {
      FitCapture c;
      c.kind = CaptureKind::kTurntable;
      c.radius_m = r;
      c.rpm = 120.0;
      plan.push_back({-w * w * r * Eigen::Vector3d::Unit(radial) + kG * Eigen::Vector3d::Unit(up), c});
    }
  return plan;
}

// Exact captures of a sensor reading raw = K M f + b.
std::vector<FitCapture> Captures(const Eigen::Matrix3d& m) {
  std::vector<FitCapture> out;
  int id = 0;
  for (auto [f, c] : Plan()) {
    c.id = ++id;
    c.mean_counts = kScale.asDiagonal() * (m * f) + kBias;
    c.mean_cov_counts2 = Eigen::Matrix3d::Identity() * 1e-4;
    c.n_samples = 1000;
    out.push_back(c);
  }
  return out;
}

Eigen::Matrix3d UpperT(double a_yz, double a_zy, double a_zx) {
  Eigen::Matrix3d t;
  t << 1, -a_yz, a_zy, 0, 1, -a_zx, 0, 0, 1;
  return t;
}

double AngleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

TEST(MagnitudeFitLimits, AMountingRotationIsInvisible) {
  const Eigen::Matrix3d t = UpperT(0.0042, -0.0031, 0.0057);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(1.0 * M_PI / 180.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const FitSummary s = FitCalibration(Captures(t.inverse() * r), FitOptions{});
  ASSERT_TRUE(s.IsUsable()) << s.message;
  const SensorModel m = s.Model();
  EXPECT_LT((m.bias_counts - kBias).norm(), 1e-5);
  EXPECT_LT((m.scale_counts_per_mps2 - kScale).norm(), 1e-6);
  EXPECT_NEAR(m.a_yz_rad, 0.0042, 1e-8);
  EXPECT_NEAR(m.a_zy_rad, -0.0031, 1e-8);
  EXPECT_NEAR(m.a_zx_rad, 0.0057, 1e-8);
  const Eigen::Vector3d f(3.0, -4.0, 8.0);
  const Eigen::Vector3d ap = m.Calibrate(kScale.asDiagonal() * (t.inverse() * r * f) + kBias);
  EXPECT_NEAR(ap.norm(), f.norm(), 1e-6);
  // a^p is R f: the whole rotation is in it (here 0.84 deg of f's direction).
  EXPECT_LT((ap - r * f).norm(), 1e-6);
  EXPECT_GT(AngleBetween(ap, f), 0.01);
}

TEST(MagnitudeFitLimits, ALowerTriangularMisalignmentBecomesMagnitudeEquivalentAngles) {
  Eigen::Matrix3d l;  // axes referred to z: y leans toward z, x toward y and z
  l << 1, 0, 0, 0.004, 1, 0, -0.005, 0.006, 1;
  const FitSummary s = FitCalibration(Captures(l.inverse()), FitOptions{});
  ASSERT_TRUE(s.IsUsable()) << s.message;
  const SensorModel m = s.Model();
  // |a^p| right everywhere, also in directions the fit never saw ...
  std::mt19937_64 rng(1);
  std::normal_distribution<double> n(0.0, 1.0);
  double worst_mag = 0.0, worst_dir = 0.0;
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d f = 15.0 * Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
    const Eigen::Vector3d ap = m.Calibrate(kScale.asDiagonal() * (l.inverse() * f) + kBias);
    worst_mag = std::max(worst_mag, std::fabs(ap.norm() - f.norm()));
    worst_dir = std::max(worst_dir, AngleBetween(ap, f));
  }
  EXPECT_LT(worst_mag, 1e-6);
  // ... the angles are not L's (which has none in the upper triangle) ...
  EXPECT_GT(std::fabs(m.a_yz_rad) + std::fabs(m.a_zy_rad) + std::fabs(m.a_zx_rad), 0.004);
  // ... and directions are off by a rotation of the misalignment's size.
  EXPECT_GT(worst_dir, 0.002);
  EXPECT_LT(worst_dir, 0.02);
}

}  // namespace
}  // namespace accelcal::magnitude_fit_limits_test
