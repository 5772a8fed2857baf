// The adaptive stop: a sample count fixed before the capture, within its minimum and maximum, in
// whole revolutions on the turntable.
#include "accelcal/calibration/capture_stop_rule.h"

#include <gtest/gtest.h>

namespace accelcal::capture_stop_rule_test {
namespace {

TEST(CaptureStopRule, StaticCaptureCountsThePlannedSamples) {
  const CaptureStopRule rule = CaptureStopRule::For(7.3, 100.0, 1.0, 60.0);
  EXPECT_EQ(rule.needed_samples, 730);
  EXPECT_EQ(rule.min_samples, 100);
  EXPECT_EQ(rule.max_samples, 6000);
  EXPECT_FALSE(rule.Enough(729));
  EXPECT_TRUE(rule.Enough(730));
  EXPECT_DOUBLE_EQ(rule.Progress(365), 0.5);
  EXPECT_DOUBLE_EQ(rule.Progress(1000), 1.0);
  EXPECT_DOUBLE_EQ(rule.RemainingS(630, 100.0), 1.0);
  EXPECT_DOUBLE_EQ(rule.RemainingS(800, 100.0), 0.0);
}

TEST(CaptureStopRule, NeverShorterThanTheMinimumNorLongerThanTheMaximum) {
  EXPECT_EQ(CaptureStopRule::For(0.2, 100.0, 2.0, 60.0).needed_samples, 200);
  EXPECT_EQ(CaptureStopRule::For(500.0, 100.0, 2.0, 60.0).needed_samples, 6000);
  // A maximum below the minimum: the minimum wins.
  const CaptureStopRule odd = CaptureStopRule::For(5.0, 100.0, 3.0, 1.0);
  EXPECT_EQ(odd.min_samples, 300);
  EXPECT_EQ(odd.max_samples, 300);
  EXPECT_EQ(odd.needed_samples, 300);
}

TEST(CaptureStopRule, TurntableRunsEndOnWholeRevolutions) {
  // 120 rpm at 100 Hz: 50 samples a revolution. 7.31 s = 731 samples -> 15 turns = 750.
  const CaptureStopRule rule = CaptureStopRule::For(7.31, 100.0, 1.0, 60.0, 120.0);
  EXPECT_EQ(rule.needed_samples, 750);
  EXPECT_EQ(rule.min_samples, 100);
  EXPECT_EQ(rule.max_samples, 6000);
  // 90 rpm at 100 Hz: 66.7 samples a turn; a 1 s minimum is two turns (134), the 10.1 s maximum
  // 15 turns (1000).
  const CaptureStopRule slow = CaptureStopRule::For(0.5, 100.0, 1.0, 10.1, 90.0);
  EXPECT_EQ(slow.min_samples, 134);
  EXPECT_EQ(slow.needed_samples, 134);
  EXPECT_EQ(CaptureStopRule::For(50.0, 100.0, 1.0, 10.1, 90.0).needed_samples, 1000);
}

}  // namespace
}  // namespace accelcal::capture_stop_rule_test
