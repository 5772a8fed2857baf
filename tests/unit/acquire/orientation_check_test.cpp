#include "accelcal/acquire/capture_engine/orientation_check.h"

#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "test_support.h"

namespace accelcal::orientation_check_test {
namespace {

using testing::Contains;

constexpr double kG = 9.80665;

// The true sensor reads; the check only knows a rough model (3 % scale, 15 counts of bias off).
struct Bench {
  SensorModel truth = sim::DefaultScenario().sensor.model;
  SensorModel rough;
  Bench() {
    rough.bias_counts = truth.bias_counts + Eigen::Vector3d(15, -15, 10);
    rough.scale_counts_per_mps2 = truth.scale_counts_per_mps2 * 1.03;
  }
  Eigen::Vector3d MeanRaw(const Eigen::Vector3d& up) const {
    return truth.Raw(kG * up.normalized());
  }
};

const NamedPose kZUp{"+z", Eigen::Vector3d::UnitZ()};

TEST(OrientationCheck, ExpectedPoseIsAccepted) {
  const Bench b;
  const OrientationVerdict v =
      CheckOrientation(b.MeanRaw({0, 0, 1}), b.rough, kZUp, {}, {}, OrientationOptions{});
  EXPECT_TRUE(v.ok) << v.reason;
  EXPECT_LT(v.angle_to_expected_deg, 5.0);  // the rough bias turns it ~3.5 deg
  EXPECT_EQ(v.nearest_pose, "+z");
}

TEST(OrientationCheck, WrongFaceIsNamed) {
  const Bench b;
  const OrientationVerdict v =
      CheckOrientation(b.MeanRaw({0, -1, 0}), b.rough, kZUp, {}, {}, OrientationOptions{});
  EXPECT_FALSE(v.ok);
  EXPECT_EQ(v.reason, "the prism sits on the wrong face: -y is up, expected +z");
  EXPECT_NEAR(v.angle_to_expected_deg, 90.0, 3.0);
}

TEST(OrientationCheck, WrongKnownPoseIsNamed) {
  const Bench b;
  const NamedPose tilted{"tilted +x+y-z", Eigen::Vector3d(1, 1, -1)};
  const OrientationVerdict v = CheckOrientation(b.MeanRaw({1, 1, -1}), b.rough, kZUp, {},
                                                {tilted}, OrientationOptions{});
  EXPECT_EQ(v.reason, "the sensor is in pose 'tilted +x+y-z', expected '+z'");
}

TEST(OrientationCheck, DuplicatePoseIsRefused) {
  const Bench b;
  const std::vector<CapturedPose> captured = {{1, "x up", Eigen::Vector3d::UnitX()},
                                              {3, "z up", Eigen::Vector3d::UnitZ()}};
  const OrientationVerdict v =
      CheckOrientation(b.MeanRaw({0, 0, 1}), b.rough, kZUp, captured, {}, OrientationOptions{});
  EXPECT_FALSE(v.ok);
  EXPECT_EQ(v.reason, "this pose was already captured as capture 3 (z up)");
}

TEST(OrientationCheck, ToleranceIsRespected) {
  const Bench b;
  OrientationOptions options;
  options.tolerance_deg = 15.0;
  for (const double tilt_deg : {8.0, 25.0}) {
    // Tilted about x away from +z: far from every face.
    const Eigen::Vector3d up =
        Eigen::AngleAxisd(tilt_deg * M_PI / 180.0, Eigen::Vector3d::UnitX()) * kZUp.up;
    const OrientationVerdict v = CheckOrientation(b.MeanRaw(up), b.rough, kZUp, {}, {}, options);
    EXPECT_NEAR(v.angle_to_expected_deg, tilt_deg, 3.0);
    EXPECT_EQ(v.ok, tilt_deg < options.tolerance_deg) << v.reason;
    if (!v.ok) {
      EXPECT_TRUE(Contains(v.reason, "deg from the expected pose (+z), tolerance 15 deg"))
          << v.reason;
    }
  }
}

TEST(OrientationCheck, HelpersAndOptions) {
  EXPECT_EQ(DescribeUp({0, 0, -2}), "-z");
  EXPECT_EQ(DescribeUp({1, 0, 1}), "(0.71, 0.00, 0.71)");
  EXPECT_NEAR(AngleBetweenDeg({1, 0, 0}, {0, 1, 0}), 90.0, 1e-12);
  EXPECT_NEAR(AngleBetweenDeg({1, 0, 0}, {1, 1e-9, 0}), 1e-9 * 180 / M_PI, 1e-15);
  OrientationOptions bad;
  bad.tolerance_deg = 50;
  EXPECT_TRUE(Contains(bad.Validate(), "tolerance_deg"));
}

}  // namespace
}  // namespace accelcal::orientation_check_test
