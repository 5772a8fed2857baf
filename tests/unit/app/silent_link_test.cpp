// Issue 17, item 6: a link that stays connected but sends nothing (or nothing readable) must not
// hang a capture or a noise-floor measurement: the capture engine counts its timeout in sample
// time, which stops with the samples, so StepAcquisition::Watch times them out on the wall
// clock. The wall clock is given to it here (no sleeping, nothing timed in the test).
#include "accelcal/app/wizard/step_acquisition.h"

#include <memory>

#include <gtest/gtest.h>

#include "accelcal/session/session_journal.h"
#include "capture_engine_support.h"
#include "test_support.h"

namespace accelcal::silent_link_test {
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

// The record step (the long drift record) on a link that falls silent: samples came, then none
// (or only unreadable lines). It had no wall-clock limit and waited forever (this failed: Watch
// said nothing for a record). Now it ends after the record's silence limit, with a plain
// reason, and the record is kept up to the last good sample (the chunk being filled committed).
TEST(SilentLink, ARecordOnALinkThatFallsSilentEndsAndKeepsWhatItRecorded) {
  std::unique_ptr<SessionJournal> journal = MakeMemoryJournal();
  RecordStepWriterOptions o;
  o.duration_s = 3600.0;
  o.chunk_s = 10.0;
  o.noise_std_counts = {1.5, 1.5, 1.7};
  o.wall_now_s = [] { return 1.7e9; };
  StepAcquisition acq(2.0);
  acq.StartRecord(std::make_unique<RecordStepWriter>(*journal, "drift", o), false, kWall0, 60.0);
  testing::SyntheticStream stream(kModel, 1.5);
  const std::vector<Sample> still = stream.Pose({0, 0, 1}, 25.0);  // 2 chunks and a half
  EXPECT_EQ(acq.Feed(still, kWall0 + 25.0), AcquisitionEvent::kNone);
  // Only unreadable lines from now on: they are not samples.
  Sample nan_line;
  nan_line.t_s = kNaN;
  nan_line.raw_counts = Eigen::Vector3d::Constant(kNaN);
  EXPECT_EQ(acq.Feed({nan_line, nan_line}, kWall0 + 50.0), AcquisitionEvent::kNone);
  EXPECT_EQ(acq.Watch(kWall0 + 84.0), AcquisitionEvent::kNone);
  EXPECT_TRUE(acq.recording());
  ASSERT_EQ(acq.Watch(kWall0 + 86.0), AcquisitionEvent::kRecordSilent);
  EXPECT_FALSE(acq.recording());
  EXPECT_TRUE(acq.ended_silent());
  EXPECT_TRUE(Contains(acq.reason(), "no samples for 61 s: the record stopped")) << acq.reason();
  const JournalRecord record = ReadRecord(*journal, "drift");
  ASSERT_EQ(record.samples.size(), still.size());
  EXPECT_EQ(record.samples.back().t_s, still.back().t_s);
}

// A record whose link sends nothing at all from its start ends the same way, with nothing stored.
TEST(SilentLink, ARecordWithNoSampleAtAllEnds) {
  std::unique_ptr<SessionJournal> journal = MakeMemoryJournal();
  RecordStepWriterOptions o;
  o.wall_now_s = [] { return 1.7e9; };
  StepAcquisition acq(2.0);
  acq.StartRecord(std::make_unique<RecordStepWriter>(*journal, "drift", o), true, kWall0, 60.0);
  EXPECT_EQ(acq.Watch(kWall0 + 59.0), AcquisitionEvent::kNone);
  ASSERT_EQ(acq.Watch(kWall0 + 61.0), AcquisitionEvent::kRecordSilent);
  EXPECT_TRUE(ReadRecord(*journal, "drift").samples.empty());
}

}  // namespace
}  // namespace accelcal::silent_link_test
