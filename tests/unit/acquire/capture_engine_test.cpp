#include "accelcal/acquire/capture_engine/capture_engine.h"

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "capture_engine_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

using testing::Contains;

const SensorModel kModel = sim::DefaultScenario().sensor.model;

CaptureContext Context(std::vector<CapturedPose> captured = {}) {
  CaptureContext c;
  c.rough_model = kModel;
  c.noise_floor = NoiseFloor::Given({1.5, 1.5, 1.7});
  c.captured = std::move(captured);
  return c;
}

CaptureRequest StaticRequest() {
  CaptureRequest r;
  r.id = 4;
  r.label = "z up";
  r.expected = {"+z", Eigen::Vector3d::UnitZ()};
  r.duration_s = 5.0;
  r.timeout_s = 60.0;
  return r;
}

// Feeds `samples` in chunks of 37 (as a source would), recording every state seen.
std::vector<CaptureState> FeedAll(CaptureEngine& engine, const std::vector<Sample>& samples) {
  std::vector<CaptureState> seen{engine.state()};
  for (size_t i = 0; i < samples.size(); i += 37) {
    const size_t end = std::min(samples.size(), i + 37);
    engine.Feed(std::vector<Sample>(samples.begin() + static_cast<long>(i),
                                    samples.begin() + static_cast<long>(end)));
    if (engine.state() != seen.back()) seen.push_back(engine.state());
  }
  return seen;
}

TEST(CaptureEngine, StillSensorIsAcceptedAfterSettling) {
  CaptureEngine engine(StaticRequest(), CaptureEngineOptions{}, Context());
  const std::vector<Sample> samples =
      testing::FirstCaptureSamples(testing::OnePose({0, 0, 1}, 20.0));
  double last_progress = 0.0;
  for (const Sample& s : samples) {
    engine.Feed(s);
    const CaptureSnapshot snap = engine.Snapshot();
    EXPECT_GE(snap.progress, last_progress - (snap.state == CaptureState::kCapturing ? 0 : 1));
    last_progress = snap.progress;
  }
  ASSERT_EQ(engine.state(), CaptureState::kAccepted) << engine.Snapshot().reason;
  const Capture& c = engine.capture();
  EXPECT_EQ(c.id, 4);
  EXPECT_EQ(c.label, "z up");
  EXPECT_EQ(c.samples.size(), 500u);  // 5 s at 100 Hz
  EXPECT_NEAR(c.samples.front().t_s, 2.0, 0.06);  // after the 2 s settle window
  EXPECT_EQ(engine.capture_stats().n, 500);
  EXPECT_EQ(engine.Snapshot().progress, 1.0);
  EXPECT_EQ(engine.Snapshot().attempts, 1);
}

TEST(CaptureEngine, BumpRestartsTheCaptureWhichIsAcceptedOnceStill) {
  sim::Scenario scenario = testing::OnePose({0, 0, 1}, 20.0);
  scenario.effects.bumps.push_back({0, 4.0, 2.0, 0.1});  // 2 s into the capture
  CaptureEngine engine(StaticRequest(), CaptureEngineOptions{}, Context());
  const std::vector<CaptureState> seen =
      FeedAll(engine, testing::FirstCaptureSamples(scenario));
  const std::vector<CaptureState> expected = {CaptureState::kSettling, CaptureState::kCapturing,
                                              CaptureState::kRetrying, CaptureState::kCapturing,
                                              CaptureState::kAccepted};
  EXPECT_EQ(seen, expected);
  EXPECT_EQ(engine.Snapshot().attempts, 2);
  // The accepted capture starts after the bump has left the settle window.
  EXPECT_GT(engine.capture().samples.front().t_s, 6.0);
}

TEST(CaptureEngine, RetryingSaysWhatFailed) {
  sim::Scenario scenario = testing::OnePose({0, 0, 1}, 4.2);
  scenario.effects.bumps.push_back({0, 4.0, 2.0, 0.1});
  CaptureEngine engine(StaticRequest(), CaptureEngineOptions{}, Context());
  FeedAll(engine, testing::FirstCaptureSamples(scenario));
  ASSERT_EQ(engine.state(), CaptureState::kRetrying);
  EXPECT_TRUE(Contains(engine.Snapshot().reason, "spike: ")) << engine.Snapshot().reason;
}

TEST(CaptureEngine, TimesOutWithTheLastProblem) {
  testing::SyntheticStream stream(kModel, 1.5);
  CaptureEngine engine(StaticRequest(), CaptureEngineOptions{}, Context());
  FeedAll(engine, stream.Pose({0, 0, 1}, 70.0, 5.0));  // a hand on the table throughout
  ASSERT_EQ(engine.state(), CaptureState::kTimedOut);
  const std::string reason = engine.Snapshot().reason;
  EXPECT_TRUE(Contains(reason, "no stable capture within 60 s: last problem: moving: x std "))
      << reason;
  EXPECT_TRUE(engine.finished());
  EXPECT_NEAR(engine.Snapshot().elapsed_s, 60.0, 0.2);
}

TEST(CaptureEngine, NaNRejectsWithTheReason) {
  testing::SyntheticStream stream(kModel, 1.5);
  std::vector<Sample> samples = stream.Pose({0, 0, 1}, 4.0);
  samples[300].raw_counts.y() = kNaN;
  CaptureEngine engine(StaticRequest(), CaptureEngineOptions{}, Context());
  FeedAll(engine, samples);
  ASSERT_EQ(engine.state(), CaptureState::kRejected);
  EXPECT_EQ(engine.Snapshot().reason, "1 sample is NaN or infinite (first at t = 3 s)");
}

TEST(CaptureEngine, ClippingAtTheAdcRangeRejectsWithTheReason) {
  sim::Scenario scenario = testing::OnePose({0, 0, 1}, 20.0);
  scenario.sensor.model.bias_counts.z() = 3757.0;  // z up reads ~4094 +- noise: it clips
  CaptureEngineOptions options;
  options.screening.adc_range = scenario.adc.Range();
  CaptureContext context = Context();
  context.rough_model.bias_counts.z() = 3757.0;
  CaptureEngine engine(StaticRequest(), options, context);
  FeedAll(engine, testing::FirstCaptureSamples(scenario));
  ASSERT_EQ(engine.state(), CaptureState::kRejected);
  EXPECT_TRUE(Contains(engine.Snapshot().reason, "z clipped at the ADC limit 4095 counts in "))
      << engine.Snapshot().reason;
}

TEST(CaptureEngine, WrongFaceIsRejectedAndNamed) {
  CaptureEngine engine(StaticRequest(), CaptureEngineOptions{}, Context());
  FeedAll(engine, testing::FirstCaptureSamples(testing::OnePose({0, -1, 0}, 10.0)));
  ASSERT_EQ(engine.state(), CaptureState::kRejected);
  EXPECT_EQ(engine.Snapshot().reason, "the prism sits on the wrong face: -y is up, expected +z");
}

TEST(CaptureEngine, DuplicatePoseIsRefused) {
  CaptureEngine engine(StaticRequest(), CaptureEngineOptions{},
                       Context({{3, "z up", Eigen::Vector3d::UnitZ()}}));
  FeedAll(engine, testing::FirstCaptureSamples(testing::OnePose({0, 0, 1}, 10.0)));
  ASSERT_EQ(engine.state(), CaptureState::kRejected);
  EXPECT_EQ(engine.Snapshot().reason, "this pose was already captured as capture 3 (z up)");
  engine.Restart();
  EXPECT_EQ(engine.state(), CaptureState::kSettling);
}

CaptureRequest TurntableRequest(double radius_m) {
  CaptureRequest r;
  r.id = 11;
  r.kind = CaptureKind::kTurntable;
  r.label = "x radial, z up";
  r.turntable.radius_m = radius_m;
  r.turntable.rpm = 120.0;
  r.duration_s = 10.0;
  return r;
}

std::vector<Sample> TurntableRun(double duration_s) {
  sim::Scenario s = sim::DefaultScenario();
  s.captures = {s.captures[10]};  // +x radial, z up, 0.10 m, 120 rpm
  s.captures[0].duration_s = duration_s;
  return testing::FirstCaptureSamples(s);
}

TEST(CaptureEngine, TurntableRunIsAccepted) {
  CaptureEngineOptions options;
  options.screening.adc_range = sim::DefaultScenario().adc.Range();
  CaptureEngine engine(TurntableRequest(0.10), options, Context());
  FeedAll(engine, TurntableRun(20.0));
  ASSERT_EQ(engine.state(), CaptureState::kAccepted) << engine.Snapshot().reason;
  EXPECT_EQ(engine.capture().radius_m, 0.10);
  EXPECT_EQ(engine.capture().kind, CaptureKind::kTurntable);
  EXPECT_TRUE(engine.Snapshot().turntable.ok);
}

TEST(CaptureEngine, TurntableRadiusInCentimetresIsCaught) {
  // Without the ADC range the plan cannot be checked: the run itself gives the unit slip away.
  CaptureEngine engine(TurntableRequest(10.0), CaptureEngineOptions{}, Context());
  FeedAll(engine, TurntableRun(20.0));
  ASSERT_EQ(engine.state(), CaptureState::kRejected);
  EXPECT_EQ(engine.Snapshot().reason,
            "radius looks 100x too large: 10 m entered; did you mean 0.1 m?");
  // With the range, the plan is refused before the table turns.
  CaptureEngineOptions options;
  options.screening.adc_range = sim::DefaultScenario().adc.Range();
  CaptureEngine planned(TurntableRequest(10.0), options, Context());
  EXPECT_EQ(planned.state(), CaptureState::kRejected);
  EXPECT_TRUE(Contains(planned.Snapshot().reason, "did you mean 0.1 m?"));
}

TEST(CaptureEngine, InvalidInputsThrow) {
  CaptureRequest bad = StaticRequest();
  bad.timeout_s = 1.0;
  EXPECT_THROW(CaptureEngine(bad, CaptureEngineOptions{}, Context()), Error);
  CaptureContext no_floor = Context();
  no_floor.noise_floor = NoiseFloor{};
  EXPECT_THROW(CaptureEngine(StaticRequest(), CaptureEngineOptions{}, no_floor), Error);
  EXPECT_EQ(CaptureStateToString(CaptureState::kTimedOut), "timed out");
}

}  // namespace
}  // namespace accelcal
