// StatusTracker: rate, gaps, and the link state machine, on a fake wall clock.
#include "accelcal/acquire/source/status_tracker.h"

#include <cmath>

#include <gtest/gtest.h>

namespace accelcal {
namespace {

std::vector<Sample> Times(double first_s, int count, double dt_s) {
  std::vector<Sample> samples(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) samples[static_cast<size_t>(i)].t_s = first_s + i * dt_s;
  return samples;
}

TEST(StatusTrackerTest, RateIsTheMedianIntervalAndUnknownAtFirst) {
  StatusTracker tracker(3.0, 2.0, 0.0);
  EXPECT_TRUE(std::isnan(tracker.status().rate_hz));
  ReadResult r;
  std::vector<Sample> s = Times(0.0, 200, 0.01);
  s[100].t_s += 0.004;  // jitter on one sample does not move a median
  tracker.OnSamples(s.data(), static_cast<long>(s.size()), 0.0, &r);
  EXPECT_NEAR(tracker.status().rate_hz, 100.0, 1e-6);
  EXPECT_EQ(tracker.status().samples_total, 200);
  EXPECT_EQ(r.samples, 200);
  EXPECT_EQ(tracker.status().gaps, 0);
}

TEST(StatusTrackerTest, GapIsReportedWithItsSize) {
  StatusTracker tracker(3.0, 2.0, 0.0);
  ReadResult r;
  std::vector<Sample> s = Times(0.0, 50, 0.01);
  tracker.OnSamples(s.data(), 50, 0.0, &r);
  std::vector<Sample> after = Times(1.49, 10, 0.01);  // 1.0 s after 0.49: 0.99 s missing
  tracker.OnSamples(after.data(), 10, 0.1, &r);
  EXPECT_EQ(r.gaps, 1);
  EXPECT_EQ(tracker.status().gaps, 1);
  EXPECT_DOUBLE_EQ(tracker.status().last_gap.t_before_s, 0.49);
  EXPECT_DOUBLE_EQ(tracker.status().last_gap.t_after_s, 1.49);
  EXPECT_NEAR(tracker.status().last_gap.missing_s, 0.99, 1e-9);
}

TEST(StatusTrackerTest, SilenceMakesTheLinkDeadAndSamplesBringItBack) {
  StatusTracker tracker(3.0, 2.0, 100.0);
  ReadResult r;
  tracker.OnLinkUp(100.0, &r);
  EXPECT_EQ(tracker.status().link, LinkState::kUp);
  tracker.Tick(101.0, &r);
  EXPECT_FALSE(r.went_dead);
  tracker.Tick(102.5, &r);
  EXPECT_TRUE(r.went_dead);
  EXPECT_EQ(tracker.status().link, LinkState::kDead);
  EXPECT_EQ(tracker.status().link_error, "no sample for 2.5 s");
  ReadResult back;
  std::vector<Sample> s = Times(0.0, 3, 0.01);
  tracker.OnSamples(s.data(), 3, 103.0, &back);
  EXPECT_TRUE(back.reconnected);
  EXPECT_EQ(tracker.status().link, LinkState::kUp);
  EXPECT_EQ(tracker.status().reconnects, 1);
  EXPECT_TRUE(tracker.status().link_error.empty());
}

TEST(StatusTrackerTest, LostLinkIsDeadWithItsReasonUntilItIsUpAgain) {
  StatusTracker tracker(3.0, 2.0, 0.0);
  ReadResult r;
  tracker.OnLinkUp(0.0, &r);
  tracker.OnLinkLost("serial:/dev/x@9600: read: Input/output error", &r);
  EXPECT_TRUE(r.link_lost);
  EXPECT_TRUE(r.went_dead);
  EXPECT_EQ(tracker.status().link, LinkState::kDead);
  tracker.OnOpenFailed("open /dev/x: No such file or directory");
  EXPECT_EQ(tracker.status().link_error, "open /dev/x: No such file or directory");
  ReadResult up;
  tracker.OnLinkUp(5.0, &up);
  EXPECT_TRUE(up.reconnected);
  EXPECT_EQ(tracker.status().link, LinkState::kUp);
}

TEST(StatusTrackerTest, ANewReasonForTheSilenceIsSaidAndBecomesTheDeadLinksReason) {
  StatusTracker tracker(3.0, 2.0, 100.0);
  ReadResult r;
  tracker.OnLinkUp(100.0, &r);
  tracker.Tick(102.5, &r, "heartbeats arrive, but no HIGHRES_IMU");
  EXPECT_EQ(tracker.status().link_error, "no sample for 2.5 s: heartbeats arrive, but no HIGHRES_IMU");
  ReadResult later;
  tracker.OnSilenceReason("no heartbeat for 3.1 s: the vehicle is gone", 103.5, &later);
  EXPECT_TRUE(later.notice);
  EXPECT_EQ(tracker.status().last_notice, "no heartbeat for 3.1 s: the vehicle is gone");
  EXPECT_EQ(tracker.status().link_error, "no sample for 3.5 s: no heartbeat for 3.1 s: the vehicle is gone");
}

TEST(StatusTrackerTest, ANewReasonForTheSilenceKeepsAConnectionError) {
  StatusTracker tracker(3.0, 2.0, 0.0);
  ReadResult r;
  tracker.OnLinkUp(0.0, &r);
  tracker.OnLinkLost("tcp:127.0.0.1:5760: connection reset by peer", &r);
  tracker.OnSilenceReason("no heartbeat for 3.1 s: the vehicle is gone", 4.0, &r);
  EXPECT_TRUE(r.notice);
  EXPECT_EQ(tracker.status().link_error, "tcp:127.0.0.1:5760: connection reset by peer");
}

TEST(StatusTrackerTest, EndedIsFinal) {
  StatusTracker tracker(3.0, 0.5, 0.0);
  ReadResult r;
  tracker.OnEnded(&r);
  EXPECT_TRUE(r.ended);
  tracker.Tick(10.0, &r);
  EXPECT_EQ(tracker.status().link, LinkState::kEnded);
  EXPECT_EQ(LinkStateToString(LinkState::kEnded), "ended");
}

}  // namespace
}  // namespace accelcal
