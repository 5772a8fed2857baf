// Issue 17, item 6: a link that stays connected but sends nothing (or nothing readable) must not
// hang a capture or a noise-floor measurement: the capture engine counts its timeout in sample
// time, which stops with the samples, so StepAcquisition::Watch times them out on the wall
// clock. The wall clock is given to it here (no sleeping, nothing timed in the test).
#include "accelcal/app/wizard/step_acquisition.h"

#include <gtest/gtest.h>

#include "capture_engine_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

using testing::Contains;

const SensorModel kModel = sim::DefaultScenario().sensor.model;

CaptureContext Context() {
  CaptureContext c;
  c.rough_model = kModel;
  c.noise_floor = NoiseFloor::Given({1.5, 1.5, 1.7});
  return c;
}

CaptureRequest StaticRequest() {
  CaptureRequest r;
  r.id = 1;
  r.label = "z up";
  r.expected = {"+z", Eigen::Vector3d::UnitZ()};
  r.duration_s = 5.0;
  r.timeout_s = 20.0;
  return r;
}

constexpr double kWall0 = 1000.0;

TEST(SilentLink, ACaptureWithNoSampleAtAllTimesOutOnTheWallClock) {
  StepAcquisition acq(2.0);
  acq.StartCapture(StaticRequest(), CaptureEngineOptions{}, Context(), kWall0);
  EXPECT_EQ(acq.Watch(kWall0 + 19.0), AcquisitionEvent::kNone);
  EXPECT_TRUE(acq.capturing());
  ASSERT_EQ(acq.Watch(kWall0 + 21.0), AcquisitionEvent::kCaptureRejected);
  EXPECT_FALSE(acq.capturing());
  EXPECT_TRUE(acq.ended_silent());
  EXPECT_TRUE(Contains(acq.reason(), "no stable capture within 20 s (wall clock): no samples for 21 s"))
      << acq.reason();
}

// Samples came, the capture began, then the link went silent mid-capture: the capture engine
// would wait for sample time forever; the wall clock ends it timeout_s after the last sample.
TEST(SilentLink, ALinkThatFallsSilentDuringACaptureEndsItAfterTheTimeout) {
  StepAcquisition acq(2.0);
  acq.StartCapture(StaticRequest(), CaptureEngineOptions{}, Context(), kWall0);
  testing::SyntheticStream stream(kModel, 1.5);
  const std::vector<Sample> still = stream.Pose({0, 0, 1}, 4.0);
  AcquisitionEvent last = AcquisitionEvent::kNone;
  for (size_t i = 0; i < still.size(); i += 10)
    last = acq.Feed(std::vector<Sample>(still.begin() + static_cast<long>(i),
                                        still.begin() + static_cast<long>(std::min(still.size(), i + 10))),
                    kWall0 + 4.0 * static_cast<double>(i) / static_cast<double>(still.size()));
  ASSERT_EQ(last, AcquisitionEvent::kCapturing) << acq.reason();
  // Capturing, so a long capture is not cut while samples flow...
  EXPECT_EQ(acq.Watch(kWall0 + 23.0), AcquisitionEvent::kNone);
  // ...but 20 s after the last sample it is over.
  ASSERT_EQ(acq.Watch(kWall0 + 25.0), AcquisitionEvent::kCaptureRejected);
  EXPECT_TRUE(Contains(acq.reason(), "(wall clock): no samples for 21 s")) << acq.reason();
}

// Samples that are not finite (a link sending only unreadable lines) do not count as samples.
TEST(SilentLink, ANoiseFloorWithoutFiniteSamplesTimesOut) {
  StepAcquisition acq(2.0);
  acq.MeasureNoiseFloor(kWall0, 20.0);
  EXPECT_EQ(acq.Watch(kWall0 + 10.0), AcquisitionEvent::kNone);
  ASSERT_EQ(acq.Watch(kWall0 + 20.5), AcquisitionEvent::kNoiseFloorSilent);
  EXPECT_FALSE(acq.measuring_noise_floor());
  EXPECT_TRUE(Contains(acq.reason(), "no samples for 20 s: the noise floor cannot be measured"))
      << acq.reason();
}

TEST(SilentLink, AFastSimulatedBenchIsNeverCutByTheWallClock) {
  // The virtual bench at speed 0 runs far faster than real time: the wall clock barely moves,
  // and the sample-time timeout stays the one that decides.
  StepAcquisition acq(2.0);
  acq.StartCapture(StaticRequest(), CaptureEngineOptions{}, Context(), kWall0);
  testing::SyntheticStream stream(kModel, 1.5);
  const AcquisitionEvent e = acq.Feed(stream.Pose({0, 0, 1}, 12.0), kWall0 + 0.01);
  EXPECT_EQ(e, AcquisitionEvent::kCaptureAccepted) << acq.reason();
}

}  // namespace
}  // namespace accelcal
