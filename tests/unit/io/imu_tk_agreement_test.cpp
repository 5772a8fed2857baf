// The real-data test: the imu_tk Xsens recording (tests/data/imu_tk), fitted end to end
// (read, detect static intervals, screen, fit) must agree with what the public imu_tk tool fits
// on it with g = 9.81744 m/s^2 (the figures): within 1.5 counts, 0.1 % and 1e-3 rad.
#include <string>

#include <gtest/gtest.h>

#include "accelcal/calibration/capture_screening.h"
#include "accelcal/calibration/fit/calibration_fit.h"
#include "accelcal/io/recording_reader.h"
#include "accelcal/acquire/static_detector.h"

namespace accelcal {
namespace {

const std::string kPath = std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/imu_tk/xsens_acc.mat";

TEST(ImuTkAgreement, NineParametersMatchTheReferenceTool) {
  const std::vector<Sample> samples = ReadRecordingFile(kPath);
  const StaticDetection detection = DetectStaticIntervals(samples, StaticDetectorOptions{});
  ASSERT_EQ(detection.intervals.size(), 38u);
  std::vector<Capture> captures = CapturesFromIntervals(samples, detection);
  ScreenCaptures(captures, ScreeningOptions{});
  for (const Capture& c : captures) EXPECT_TRUE(c.used()) << c.id << ": " << c.rejection_reason;

  FitOptions options;
  options.gravity = GravitySpec::Given(9.81744);
  const FitSummary s = FitCalibration(captures, options);
  ASSERT_TRUE(s.IsUsable()) << s.FullReport();
  const SensorModel m = s.Model();

  const Eigen::Vector3d bias_ref(33123.84, 33275.16, 32364.49);
  const Eigen::Vector3d scale_ref(414.42, 412.03, 414.62);
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(m.bias_counts(j), bias_ref(j), 1.5) << "bias axis " << j;
    EXPECT_NEAR(m.scale_counts_per_mps2(j) / scale_ref(j), 1.0, 1e-3) << "scale axis " << j;
  }
  EXPECT_NEAR(m.a_yz_rad, 0.00339, 1e-3);
  EXPECT_NEAR(m.a_zy_rad, -0.00930, 1e-3);
  EXPECT_NEAR(m.a_zx_rad, 0.02137, 1e-3);
  // Real poses held by hand: the fit is well conditioned and its residuals are sub-mg.
  EXPECT_LT(s.condition_number, 20.0);
  EXPECT_LT(s.residual_rms_mps2, 0.003);
}

}  // namespace
}  // namespace accelcal
