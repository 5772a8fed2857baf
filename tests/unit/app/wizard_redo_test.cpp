// Redo: b on a later step reaches an accepted capture and offers to take it again (asked first);
// the new capture supersedes the old one, both kept in the session, the old one out of the fit
// and the report; b or s before the new one is accepted keep the old one; a resumed session
// keeps the mark. The engine on the virtual bench at speed 0 (time is the samples').
#include <algorithm>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/source/sim_source.h"
#include "accelcal/app/report_inputs.h"
#include "accelcal/app/wizard/wizard_engine.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/session/procedure.h"
#include "accelcal/session/session_journal.h"
#include "accelcal/session/session_store.h"
#include "session_test_support.h"

namespace accelcal::wizard_redo_test {
namespace {

Procedure ShortStaticProcedure(int poses) {
  Procedure p = LoadProcedure(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/full_calibration.toml");
  std::vector<ProcedureStep> steps;
  for (const ProcedureStep& s : p.steps) {
    if (s.kind == StepKind::kStatic && poses-- > 0) steps.push_back(s);
    if (s.kind == StepKind::kFit || s.kind == StepKind::kReport) steps.push_back(s);
  }
  p.steps = steps;
  return p;
}

struct Rig {
  Rig(Procedure procedure, std::shared_ptr<SessionJournal> journal_in)
      : sim(sim::DefaultScenario(), [] {
          SimOptions o;
          o.speed = 0.0;
          o.bump_probability = 0.0;
          return o;
        }()),
        journal(std::move(journal_in)),
        engine(std::move(procedure), sim, *journal, WizardOptions{"test", "op", "SN1", {}, 2.0, {}}) {}
  SimSource sim;
  std::shared_ptr<SessionJournal> journal;
  WizardEngine engine;
};

bool Busy(const WizardView& v) { return v.screen == WizardScreen::kCapturing && !v.input; }

void PollUntilQuestion(WizardEngine& e) {
  for (int i = 0; i < 5000 && Busy(e.View()); ++i) e.Poll(0.0);
}

void AcceptUntil(WizardEngine& e, const std::function<bool(const WizardView&)>& stop) {
  for (int i = 0; i < 2000; ++i) {
    PollUntilQuestion(e);
    const WizardView v = e.View();
    if (v.finished || stop(v)) return;
    e.Handle({IntentKind::kAccept, ""});
  }
  FAIL() << "the wizard did not get there";
}

// The step's own prompt (the noise floor measured first when it is asked).
auto AtPose(const std::string& title) {
  return [title](const WizardView& v) {
    return v.step_title == title && v.prompt.rfind("Put the prism", 0) == 0;
  };
}

bool HasLine(const WizardView& v, const std::string& part) {
  return std::any_of(v.lines.begin(), v.lines.end(),
                     [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

void Press(WizardEngine& e, IntentKind kind) { e.Handle({kind, ""}); }

TEST(WizardRedoTest, BackOnAnAcceptedCaptureAsksThenTakesItAgain) {
  Rig rig(ShortStaticProcedure(9), MakeMemoryJournal());
  AcceptUntil(rig.engine, AtPose("-z up"));
  Press(rig.engine, IntentKind::kBack);
  WizardView v = rig.engine.View();
  EXPECT_EQ(v.step_title, "+z up");
  EXPECT_NE(v.prompt.find("Take '+z up' again? Its capture 1 was accepted"), std::string::npos) << v.prompt;
  ASSERT_FALSE(v.keys.empty());
  EXPECT_EQ(v.keys[0].action, "take it again");
  Press(rig.engine, IntentKind::kAnswerNo);  // n keeps it
  EXPECT_TRUE(AtPose("-z up")(rig.engine.View()));
  ASSERT_EQ(rig.journal->Captures().size(), 1u);

  Press(rig.engine, IntentKind::kBack);
  Press(rig.engine, IntentKind::kAccept);  // take it again
  v = rig.engine.View();
  EXPECT_EQ(v.step_title, "+z up");
  EXPECT_TRUE(HasLine(v, "Taking '+z up' again: capture 1 stays until this one is accepted")) << v.prompt;
  AcceptUntil(rig.engine, AtPose("-z up"));
  const std::vector<JournalCapture> all = rig.journal->Captures();
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].step_id, "pose_pz");
  EXPECT_EQ(all[0].superseded_by, "pose_pz#2");
  EXPECT_EQ(all[1].step_id, "pose_pz#2");
  EXPECT_FALSE(all[1].superseded());
  EXPECT_TRUE(HasLine(rig.engine.View(), "capture 2 replaces capture 1")) << rig.engine.View().prompt;
}

TEST(WizardRedoTest, BackOrSkipBeforeTheNewCaptureKeepsTheOldOne) {
  Rig rig(ShortStaticProcedure(9), MakeMemoryJournal());
  AcceptUntil(rig.engine, AtPose("-z up"));
  for (IntentKind cancel : {IntentKind::kBack, IntentKind::kSkip}) {
    Press(rig.engine, IntentKind::kBack);
    Press(rig.engine, IntentKind::kAccept);
    ASSERT_EQ(rig.engine.View().step_title, "+z up");
    Press(rig.engine, cancel);
    const WizardView v = rig.engine.View();
    EXPECT_TRUE(AtPose("-z up")(v)) << v.step_title << ": " << v.prompt;
    EXPECT_TRUE(HasLine(v, "Kept the earlier capture 1 of '+z up'"));
    const std::vector<JournalCapture> all = rig.journal->Captures();
    ASSERT_EQ(all.size(), 1u);
    EXPECT_FALSE(all[0].superseded());
    EXPECT_EQ(rig.journal->DoneSteps().count("pose_pz"), 0u);  // never recorded as skipped
  }
}

TEST(WizardRedoTest, BackWalksFurtherBackFromTheOffer) {
  Rig rig(ShortStaticProcedure(9), MakeMemoryJournal());
  AcceptUntil(rig.engine, AtPose("+x up"));
  Press(rig.engine, IntentKind::kBack);
  EXPECT_EQ(rig.engine.View().step_title, "-z up");
  Press(rig.engine, IntentKind::kBack);
  EXPECT_EQ(rig.engine.View().step_title, "+z up");
  Press(rig.engine, IntentKind::kBack);  // nothing before it: the offer stays
  EXPECT_NE(rig.engine.View().problem.find("nothing to go back to"), std::string::npos);
  Press(rig.engine, IntentKind::kAccept);
  EXPECT_EQ(rig.engine.View().step_title, "+z up");
  AcceptUntil(rig.engine, AtPose("+x up"));
  const std::vector<JournalCapture> current = CurrentCaptures(rig.journal->Captures());
  ASSERT_EQ(current.size(), 2u);
  EXPECT_EQ(current[0].step_id, "pose_mz");
  EXPECT_EQ(current[1].step_id, "pose_pz#2");
}

// The fit and the report use the redo's capture only; a resumed session keeps the mark and goes
// on where it was (the superseded capture is not asked for again).
using WizardRedoStoreTest = testing::SessionDirTest;

TEST_F(WizardRedoStoreTest, TheFitAndTheReportLeaveTheSupersededCaptureOutAndAResumeKeepsTheMark) {
  const std::string path = path_;
  SessionOpenOptions writer;
  writer.procedure = "short";
  writer.source = "sim";
  {
    std::shared_ptr<SessionJournal> store = SessionStore::Open(path, writer);
    Rig rig(ShortStaticProcedure(9), store);
    AcceptUntil(rig.engine, AtPose("+y up"));
    Press(rig.engine, IntentKind::kBack);
    Press(rig.engine, IntentKind::kAccept);
    ASSERT_EQ(rig.engine.View().step_title, "-x up");
    AcceptUntil(rig.engine, AtPose("+y up"));
    Press(rig.engine, IntentKind::kQuit);
  }
  std::shared_ptr<SessionJournal> store = SessionStore::Open(path, writer);
  const std::vector<JournalCapture> all = store->Captures();
  ASSERT_EQ(all.size(), 5u);
  EXPECT_EQ(all[3].step_id, "pose_mx");
  EXPECT_EQ(all[3].superseded_by, "pose_mx#2");
  EXPECT_EQ(all[4].step_id, "pose_mx#2");
  Rig rig(ShortStaticProcedure(9), store);
  EXPECT_EQ(rig.engine.View().step_title, "+y up");  // resumed after the redo, not at -x up
  AcceptUntil(rig.engine, [](const WizardView&) { return false; });
  ASSERT_TRUE(rig.engine.completed());
  EXPECT_EQ(store->Captures().size(), 10u);  // 9 poses and the superseded one
  EXPECT_NE(store->DoneSteps().at("fit").find("fit converged: 9 captures"), std::string::npos)
      << store->DoneSteps().at("fit");
  const ReportInputs in = ReportInputsFromJournal(*store, path);
  EXPECT_EQ(in.captures.size(), 9u);
  EXPECT_EQ(std::count_if(in.captures.begin(), in.captures.end(),
                          [&](const ReportCaptureStats& c) { return c.id == all[3].capture.id; }),
            0);
}

}  // namespace
}  // namespace accelcal::wizard_redo_test
