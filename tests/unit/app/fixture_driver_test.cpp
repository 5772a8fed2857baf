// A sensor left out of a pose on a fixture (app/fixture/fixture_driver.h): named, asked about
// on top of the engine's screens, retried alone (its own new span, recorded under the pose's
// step, the others untouched) or left out with its reason; Enter takes the recommended answer
// (retry while its link is up and the plate still reads as in the pose; leave out a dead one).
#include "accelcal/app/fixture/fixture_driver.h"

#include <gtest/gtest.h>

#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/app/fixture/sensor_batch.h"
#include "accelcal/app/fixture/sensor_look.h"
#include "fixture_test_support.h"

namespace accelcal::fixture_driver_test {
namespace {

using fixture_test::Plate;

// The engine seen by the driver: reads the lead (as the engine's Poll does), shows the next
// step's placement, and keeps the intents it was given.
class EngineStandIn final : public WizardDriver {
 public:
  explicit EngineStandIn(FixtureLeadSource& source) : source_(source) {}
  void Poll(double timeout_s) override {
    std::vector<Sample> drop;
    source_.Read(timeout_s, &drop);
  }
  void Handle(const Intent& intent) override { intents.push_back(intent.kind); }
  WizardView View() const override {
    WizardView v;
    v.screen = WizardScreen::kPlacePose;
    v.step_title = "next pose";
    v.prompt = "Put the prism on the table with +z up; press Enter to capture.";
    v.expected_up = Eigen::Vector3d::UnitZ();
    v.keys = {{"Enter", "capture"}};
    return v;
  }
  std::vector<IntentKind> intents;

 private:
  FixtureLeadSource& source_;
};

struct Bench {
  Procedure procedure = fixture_test::OnePoseAndATurntable();
  FixtureLeadSource lead{Plate(), 30.0, 1.0};
  std::unique_ptr<SessionJournal> session = MakeMemoryJournal();
  FixtureJournal journal{*session, lead, procedure};
  EngineStandIn engine{lead};
  FixtureWizardDriver driver{engine, journal, lead};

  // The driver polled for `seconds` of the bench's time.
  void PollFor(double seconds) {
    const double until_s = lead.bench()->now_s() + seconds;
    while (lead.bench()->now_s() < until_s) driver.Poll(0.1);
  }
  // The plate on +x, settled, and the lead's capture of 3 s accepted (the loose board still
  // rocks then; the dead one says nothing).
  void CapturePose(const std::string& step_id = "pose_px") {
    lead.bench()->PlaceStatic(Eigen::Vector3d::UnitX(), 0.0);
    std::vector<Sample> samples;
    const double settled_s = lead.bench()->now_s() + 0.6;
    while (lead.bench()->now_s() < settled_s) lead.Read(1.0, &samples);
    samples.clear();
    const double until_s = lead.bench()->now_s() + 3.0;
    while (samples.empty() || samples.back().t_s < until_s) lead.Read(1.0, &samples);
    Capture c;
    c.id = 1;
    c.label = "x up";
    c.samples = samples;
    journal.RecordCapture(step_id, c);
    driver.Poll(0.0);
  }
};

TEST(FixtureDriver, ALooseBoardRetriedAloneADeadOneLeftOutTheOthersKept) {
  Bench b;
  b.CapturePose();
  ASSERT_EQ(b.session->SensorCaptures(1).size(), 1u);  // the lead
  ASSERT_EQ(b.session->SensorCaptures(2).size(), 1u);  // board 3
  const std::vector<Sample> board3 = b.session->SensorCaptures(2)[0].capture.samples;

  // Asked about the loose board first: named, why, and retry recommended (alive, plate held).
  ASSERT_TRUE(b.driver.Asking());
  WizardView v = b.driver.View();
  EXPECT_NE(v.problem.find("sensor 1 (SIM01) left out of 'x up'"), std::string::npos) << v.problem;
  EXPECT_NE(v.problem.find("not still"), std::string::npos) << v.problem;
  EXPECT_TRUE(b.driver.RecommendsRetry());
  ASSERT_FALSE(v.keys.empty());
  EXPECT_EQ(v.keys[0].key, "Enter");
  EXPECT_EQ(v.keys[0].action, "retry alone (recommended)");
  EXPECT_FALSE(v.finished);
  // The plate is still in the pose asked about (the engine's next placement waits beneath).
  EXPECT_EQ(v.step_title, "x up: sensor 1 (SIM01) left out");
  ASSERT_TRUE(v.expected_up.has_value());
  EXPECT_EQ(*v.expected_up, Eigen::Vector3d::UnitX());
  // A key the question does not take waits; the engine gets nothing but q.
  b.driver.Handle({IntentKind::kBack, ""});
  EXPECT_TRUE(b.engine.intents.empty());

  // The plate held: after it rested, Enter takes the loose board alone.
  b.PollFor(8.0);
  EXPECT_TRUE(b.driver.RecommendsRetry());
  b.driver.Handle({IntentKind::kAccept, ""});
  EXPECT_EQ(b.driver.View().screen, WizardScreen::kCapturing);
  EXPECT_NE(b.driver.View().prompt.find("capturing sensor 1 (SIM01) alone"), std::string::npos);
  b.PollFor(3.5);
  ASSERT_EQ(b.session->SensorCaptures(0).size(), 1u) << b.driver.View().problem;
  const JournalCapture alone = b.session->SensorCaptures(0)[0];
  EXPECT_EQ(alone.step_id, "pose_px");
  EXPECT_GT(alone.capture.samples.front().t_s, board3.back().t_s);  // a span of its own
  EXPECT_NEAR(alone.capture.samples.back().t_s - alone.capture.samples.front().t_s,
              board3.back().t_s - board3.front().t_s, 0.05);
  // The others untouched: nobody taken again.
  EXPECT_EQ(b.session->SensorCaptures(1).size(), 1u);
  EXPECT_EQ(b.session->SensorCaptures(2).size(), 1u);
  EXPECT_EQ(b.session->Inputs().at(kFixtureStepId).count(SensorRetriedKey("SIM01", "pose_px")), 1u);

  // Then the dead board: leaving it out is recommended, Enter does so.
  ASSERT_TRUE(b.driver.Asking());
  v = b.driver.View();
  EXPECT_NE(v.problem.find("sensor 4 (SIM04)"), std::string::npos) << v.problem;
  EXPECT_FALSE(b.driver.RecommendsRetry());
  EXPECT_EQ(v.keys[0].action, "leave out (recommended)");
  b.driver.Handle({IntentKind::kAccept, ""});
  EXPECT_FALSE(b.driver.Asking());
  EXPECT_TRUE(b.session->SensorCaptures(3).empty());
  EXPECT_NE(b.driver.View().notice.find("sensor 4 (SIM04) left out of 'x up'"), std::string::npos)
      << b.driver.View().notice;
  EXPECT_NE(b.session->Inputs().at(kFixtureStepId).at(SensorLeftOutKey("SIM04", "pose_px")).find("no samples"),
            std::string::npos);
  // Nothing asked any more: Enter is the engine's again.
  EXPECT_EQ(b.driver.View().step_title, "next pose");  // the engine's again
  b.driver.Handle({IntentKind::kAccept, ""});
  ASSERT_EQ(b.engine.intents.size(), 1u);
  EXPECT_EQ(b.engine.intents[0], IntentKind::kAccept);
}

TEST(FixtureDriver, ADeadBoardLeftOutOnceIsNotAskedAboutAgainWhileItStaysDead) {
  Bench b;
  b.CapturePose();
  ASSERT_TRUE(b.driver.Asking());
  b.driver.Handle({IntentKind::kSkip, ""});  // the loose board: left out
  ASSERT_TRUE(b.driver.Asking());
  EXPECT_NE(b.driver.View().problem.find("SIM04"), std::string::npos);
  b.driver.Handle({IntentKind::kAccept, ""});  // the dead one: left out (recommended)
  ASSERT_FALSE(b.driver.Asking());
  // The pose again (a redo's step): the loose board, alive, is asked about if it is left out
  // again (it may have settled by now); the dead one is left out without a question, and the
  // screen says so.
  b.CapturePose("pose_px#2");
  if (b.driver.Asking()) {
    EXPECT_NE(b.driver.View().problem.find("SIM01"), std::string::npos) << b.driver.View().problem;
    b.driver.Handle({IntentKind::kSkip, ""});
  }
  EXPECT_FALSE(b.driver.Asking()) << b.driver.View().problem;
  EXPECT_NE(b.driver.View().notice.find("sensor 4 (SIM04) left out of 'x up' as before: its link is still down"),
            std::string::npos) << b.driver.View().notice;
  // Its reason is recorded as at the first pose.
  EXPECT_NE(b.session->Inputs().at(kFixtureStepId).at(SensorLeftOutKey("SIM04", "pose_px")).find("no samples"),
            std::string::npos);
  EXPECT_TRUE(b.session->SensorCaptures(3).empty());
  EXPECT_TRUE(b.engine.intents.empty());
}

TEST(FixtureDriver, APlateMovedSinceIsNoPlaceForARetry) {
  Bench b;
  b.CapturePose();
  ASSERT_TRUE(b.driver.Asking());
  // The plate turned to its next pose before the answer: leave out is recommended; a retry
  // forced with r finds the plate elsewhere, and the board is asked about again.
  b.lead.bench()->PlaceStatic(Eigen::Vector3d::UnitZ(), 0.0);
  b.PollFor(2.0);
  EXPECT_FALSE(b.driver.RecommendsRetry());
  EXPECT_NE(b.driver.View().hint.find("moved"), std::string::npos) << b.driver.View().hint;
  b.driver.Handle({IntentKind::kRetry, ""});
  b.PollFor(3.5);
  ASSERT_TRUE(b.driver.Asking());
  const WizardView v = b.driver.View();
  EXPECT_NE(v.problem.find("again (taken alone 1 time)"), std::string::npos) << v.problem;
  EXPECT_NE(v.problem.find("not in the pose any more"), std::string::npos) << v.problem;
  EXPECT_TRUE(b.session->SensorCaptures(0).empty());
  // s leaves it out; the dead one next; q is the engine's at any moment.
  b.driver.Handle({IntentKind::kSkip, ""});
  EXPECT_NE(b.driver.View().problem.find("SIM04"), std::string::npos);
  b.driver.Handle({IntentKind::kQuit, ""});
  ASSERT_EQ(b.engine.intents.size(), 1u);
  EXPECT_EQ(b.engine.intents[0], IntentKind::kQuit);
}

TEST(FixtureDriver, EverySensorsStillnessAndOrientationOnTheScreen) {
  Bench b;
  b.lead.bench()->PlaceStatic(Eigen::Vector3d::UnitZ(), 0.0);
  b.PollFor(1.6);  // settled (0.5 s); the loose board rocks on, the dead one is silent
  WizardView v = b.driver.View();
  ASSERT_EQ(v.sensors.size(), 4u);
  EXPECT_EQ(v.sensors[0].name, "SIM01");
  EXPECT_FALSE(v.sensors[0].ok);
  EXPECT_NE(v.sensors[0].state.find("moving"), std::string::npos) << v.sensors[0].state;
  EXPECT_TRUE(v.sensors[1].ok) << v.sensors[1].state << "; " << v.sensors[1].detail;
  EXPECT_EQ(v.sensors[1].state, "still +z");
  EXPECT_TRUE(v.sensors[2].ok) << v.sensors[2].state << "; " << v.sensors[2].detail;
  EXPECT_FALSE(v.sensors[3].ok);
  EXPECT_TRUE(v.sensors[3].state == "no data" || v.sensors[3].state == "link dead") << v.sensors[3].state;
  // The plate on the wrong face for what is asked (+z): every live board shows it.
  b.lead.bench()->PlaceStatic(Eigen::Vector3d::UnitX(), 0.0);
  b.PollFor(9.0);
  v = b.driver.View();
  EXPECT_FALSE(v.sensors[1].ok);
  EXPECT_EQ(v.sensors[1].state, "still shows +x") << v.sensors[1].detail;
  EXPECT_EQ(v.sensors[0].state, "still shows +x") << v.sensors[0].detail;  // at rest by now
}

}  // namespace
}  // namespace accelcal::fixture_driver_test
