// A pose taken twice (calibration/pose_repeat.h): what moved, against the two captures' noise.
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/calibration/pose_repeat.h"

namespace accelcal {
namespace {

// A static capture of `label` at `t0_s`, 10 s at 100 Hz, reading `mean` with white noise of
// `noise_counts` on every axis.
Capture StillCapture(int id, const std::string& label, double t0_s, const Eigen::Vector3d& mean,
                     double noise_counts, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, noise_counts);
  Capture c;
  c.id = id;
  c.label = label;
  for (int k = 0; k < 1000; ++k) c.samples.push_back({t0_s + 0.01 * k, mean + Eigen::Vector3d(n(rng), n(rng), n(rng))});
  return c;
}

const Eigen::Vector3d kUp(2048.0, 2048.0, 2389.0);

// The datasheet's model: bias 2048 counts, scale 34.8 counts per m/s^2.
SensorModel Rough() {
  SensorModel m;
  m.bias_counts = Eigen::Vector3d::Constant(2048.0);
  m.scale_counts_per_mps2 = Eigen::Vector3d::Constant(34.8);
  return m;
}

TEST(PoseRepeat, ASensorThatDidNotMoveIsWithinItsNoise) {
  int beyond = 0;
  for (unsigned seed = 1; seed <= 200; ++seed) {
    const PoseRepeat r = ComparePoseRepeat(StillCapture(1, "+z up", 0.0, kUp, 1.5, seed),
                                           StillCapture(19, "+z up", 840.0, kUp, 1.5, seed + 1000), Rough());
    beyond += r.beyond_noise;
    EXPECT_NEAR(r.noise_counts, 1.5 * std::sqrt(2.0 / 1000.0), 0.01);
  }
  // One in a thousand by construction: none or one of 200.
  EXPECT_LE(beyond, 1);
}

TEST(PoseRepeat, AMoveOfAFewTimesTheNoiseIsSeenAndSaid) {
  const PoseRepeat r = ComparePoseRepeat(StillCapture(1, "+z up", 0.0, kUp, 1.5, 1),
                                         StillCapture(19, "+z up", 840.0, kUp + Eigen::Vector3d(0.0, 0.0, 0.6), 1.5, 2), Rough());
  EXPECT_TRUE(r.beyond_noise);
  EXPECT_NEAR(r.moved_counts, 0.6, 0.25);
  EXPECT_NEAR(r.elapsed_s, 840.0, 1e-6);
  EXPECT_EQ(r.label, "+z up");
  EXPECT_EQ(r.first_id, 1);
  EXPECT_EQ(r.again_id, 19);
  const std::string said = DescribePoseRepeat(r);
  EXPECT_NE(said.find("moved 0."), std::string::npos) << said;
  EXPECT_NE(said.find(" counts along gravity in 14 min, more than its noise (0.1 counts) explains"), std::string::npos) << said;
  // The settled reading is compared when the capture was still settling.
  Capture settled = StillCapture(19, "+z up", 840.0, kUp + Eigen::Vector3d(0.0, 0.0, 0.6), 1.5, 2);
  settled.settled = SettledReading{kUp, Eigen::Matrix3d::Identity() * 0.0045, Eigen::Vector3d(0.0, 0.0, 0.6)};
  EXPECT_FALSE(ComparePoseRepeat(StillCapture(1, "+z up", 0.0, kUp, 1.5, 1), settled, Rough()).beyond_noise);
}

// Set down again half a degree off: gravity turns toward x (3 counts there) but keeps its size.
TEST(PoseRepeat, APrismSetDownAgainSlightlyOffHasNotMoved) {
  const double tilt = 0.5 * M_PI / 180.0;
  const Eigen::Vector3d again(2048.0 + 341.0 * std::sin(tilt), 2048.0, 2048.0 + 341.0 * std::cos(tilt));
  const PoseRepeat r = ComparePoseRepeat(StillCapture(1, "+z up", 0.0, Eigen::Vector3d(2048.0, 2048.0, 2389.0), 1.5, 1),
                                         StillCapture(19, "+z up", 840.0, again, 1.5, 2), Rough());
  EXPECT_FALSE(r.beyond_noise) << DescribePoseRepeat(r);
  EXPECT_LT(std::abs(r.moved_counts), 0.2);
}

// On another seat (the stopped turntable's) 3 deg off the prism's pose: gravity along the first
// pose's up drops by g (1 - cos 3 deg), 0.47 counts, seven times these captures' noise; its
// magnitude does not change, and that is what is compared.
TEST(PoseRepeat, ASeatAFewDegreesOffHasNotMoved) {
  const double tilt = 3.0 * M_PI / 180.0;
  const Eigen::Vector3d again(2048.0 + 341.0 * std::sin(tilt), 2048.0, 2048.0 + 341.0 * std::cos(tilt));
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const PoseRepeat r = ComparePoseRepeat(StillCapture(1, "+z up", 0.0, Eigen::Vector3d(2048.0, 2048.0, 2389.0), 1.5, seed),
                                           StillCapture(13, "+z up", 300.0, again, 1.5, seed + 100), Rough());
    EXPECT_FALSE(r.beyond_noise) << DescribePoseRepeat(r);
    EXPECT_LT(std::abs(r.moved_counts), 0.25) << DescribePoseRepeat(r);
  }
}

// Taken again between the turntable runs and at the end: each repeat against the first, a path.
TEST(PoseRepeat, FoundInACaptureSetByLabelEveryRepeatAgainstTheFirst) {
  std::vector<Capture> set = {StillCapture(1, "+z up", 0.0, kUp, 1.5, 1),
                              StillCapture(2, "-z up", 30.0, kUp, 1.5, 2),
                              StillCapture(3, "+z up", 300.0, kUp, 1.5, 3),
                              StillCapture(4, "+z up", 600.0, kUp + Eigen::Vector3d(0, 0, 3), 1.5, 4)};
  std::vector<PoseRepeat> found = FindPoseRepeats(set, Rough());
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].first_id, 1);
  EXPECT_EQ(found[0].again_id, 3);
  EXPECT_FALSE(found[0].beyond_noise);
  EXPECT_NEAR(found[0].elapsed_s, 300.0, 1e-6);
  EXPECT_EQ(found[1].first_id, 1);
  EXPECT_EQ(found[1].again_id, 4);
  EXPECT_TRUE(found[1].beyond_noise);
  EXPECT_NEAR(found[1].moved_counts, 3.0, 0.25);
  // The path in words: each move signed, with its time since the first.
  EXPECT_EQ(RepeatedPoseLabels(found), std::vector<std::string>{"+z up"});
  const std::string path = DescribePoseRepeatPath(found, "+z up");
  EXPECT_NE(path.find("+z up, taken again 2 times"), std::string::npos) << path;
  EXPECT_NE(path.find("counts after 5 min, +3.0 counts after 10 min"), std::string::npos) << path;
  EXPECT_NE(path.find("at most 3.0 counts, more than noise explains"), std::string::npos) << path;
  EXPECT_TRUE(DescribePoseRepeatPath(found, "-z up").empty());
  // A capture left out of the fit is not compared; the pose's first used capture is the reference.
  set[3].rejection_reason = "bumped";
  found = FindPoseRepeats(set, Rough());
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].again_id, 3);
  EXPECT_FALSE(found[0].beyond_noise);
  set[0].rejection_reason = "bumped";
  EXPECT_TRUE(FindPoseRepeats(set, Rough()).empty());
  set[0].rejection_reason.clear();
  set[2].rejection_reason = "bumped";
  EXPECT_TRUE(FindPoseRepeats(set, Rough()).empty());
}

}  // namespace
}  // namespace accelcal
