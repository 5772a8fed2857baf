#include "accelcal/analysis/drift_stats.h"

#include <cmath>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

TEST(DriftStats, PeakToPeakOfMinuteMeansOfARamp) {
  DriftTracker tracker;  // 1-minute windows
  const double rate_hz = 10, slope_per_s = 0.002;
  for (int i = 0; i < 600 * 10; ++i) {  // 10 minutes
    const double t = i / rate_hz;
    tracker.Add(t, 100.0 + slope_per_s * t + ((i % 2) ? 0.5 : -0.5), kNaN);
  }
  const DriftStats s = tracker.Result();
  EXPECT_EQ(s.windows, 10);
  // Window means sit at the windows' mid-times: first at 29.95 s, last at 569.95 s.
  EXPECT_NEAR(s.max_drift, slope_per_s * 540.0, 1e-9);
  EXPECT_NEAR(s.first_mean, 100.0 + slope_per_s * 29.95, 1e-9);
  EXPECT_TRUE(std::isnan(s.temp_correlation));
  EXPECT_TRUE(std::isnan(s.temp_min_c));
}

TEST(DriftStats, ShortWindowsAtTheEndAndAcrossAGapAreLeftOut) {
  DriftTracker tracker;
  for (int i = 0; i < 1500; ++i) tracker.Add(i * 0.1, i < 600 ? 0.0 : 1.0, kNaN);  // 0..149.9 s
  // Windows [0,60) and [60,120) are full; [120,150) spans 29.9 s < 30 s: left out.
  EXPECT_EQ(tracker.Result().windows, 2);
  EXPECT_NEAR(tracker.Result().max_drift, 1.0, 1e-12);
  tracker.Add(150.0, 50.0, kNaN);  // spans 30 s now: counted, and its mean moves
  EXPECT_EQ(tracker.Result().windows, 3);
  // A gap: the next samples start at 400 s; the windows in between are simply absent.
  for (int i = 0; i < 600; ++i) tracker.Add(400.0 + i * 0.1, 2.0, kNaN);
  const DriftStats s = tracker.Result();
  EXPECT_EQ(s.windows, 4);  // [120,180) closed with 301 samples, [360,420) spans 19.9 s, [420,460) 39.9 s
}

TEST(DriftStats, TemperatureCorrelationAndSlope) {
  DriftTracker tracker;
  for (int i = 0; i < 3600 * 5; ++i) {  // 1 hour at 5 Hz, warming by 6 degC
    const double t = i / 5.0;
    const double temp = 25.0 + 6.0 * t / 3600.0;
    tracker.Add(t, 2048.0 + 0.8 * (temp - 25.0), temp);
  }
  const DriftStats s = tracker.Result();
  EXPECT_EQ(s.windows, 60);
  EXPECT_NEAR(s.temp_correlation, 1.0, 1e-9);
  EXPECT_NEAR(s.temp_slope_per_c, 0.8, 1e-9);
  EXPECT_NEAR(s.temp_max_c - s.temp_min_c, 6.0 * 59.0 / 60.0, 1e-6);
  EXPECT_NEAR(s.max_drift, 0.8 * 6.0 * 59.0 / 60.0, 1e-6);
}

TEST(DriftStats, ConstantTemperatureGivesNoSlope) {
  DriftTracker tracker;
  for (int i = 0; i < 600 * 4; ++i) tracker.Add(i * 0.25, i * 1e-3, 25.0);
  EXPECT_TRUE(std::isnan(tracker.Result().temp_slope_per_c));
  EXPECT_TRUE(std::isnan(tracker.Result().temp_correlation));
}

TEST(DriftStats, OptionsAreChecked) {
  EXPECT_THROW(DriftTracker(DriftOptions{0.0, 0.5}), Error);
  EXPECT_THROW(DriftTracker(DriftOptions{60.0, 0.0}), Error);
  EXPECT_THROW(DriftTracker(DriftOptions{60.0, 1.5}), Error);
  EXPECT_EQ(DriftTracker().Result().windows, 0);
  EXPECT_TRUE(std::isnan(DriftTracker().Result().max_drift));
}

}  // namespace
}  // namespace accelcal
