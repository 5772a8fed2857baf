// Issue 15, the capture flow: rejections in plain words about the bench (the statistics on a
// detail line), the time (this capture's seconds left, the give-up's countdown, the session's
// estimate), the confirmation of an accepted capture with its figures, and the final verdict.
// The engine runs on the clumsy bench (scenarios/clumsy_bump.toml: a knock during the tilted
// pose +x+y+z) at speed 0; line mode through its real Printer.
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/app/wizard/capture_messages.h"
#include "accelcal/app/wizard/time_estimate.h"
#include "accelcal/io/scenario_file.h"
#include "frontend.h"
#include "test_support.h"
#include "wizard_test_support.h"

namespace accelcal {
namespace {

using testing::Contains;

// ---- the words ------------------------------------------------------------------------------

// What the capture engine says (static_stability.cpp) during a knock, as seen in issue 15.
constexpr const char* kKnockReason =
    "moving: x std 1.2e+02 counts, limit 2.2; drifting: x moved 4e+02 counts over the window, limit 3; "
    "spike: z jumped -231 counts (135.1 sigma) at t = 9.64 s";

// No statistics on the main line: no std, limit, sigma or counts.
bool HasStatistics(const std::string& text) {
  return Contains(text, " std ") || Contains(text, "limit") || Contains(text, "sigma") ||
         Contains(text, "counts") || Contains(text, "t = ");
}

TEST(CaptureMessages, TheCauseComesFromTheEnginesChecks) {
  EXPECT_EQ(CauseOfReason(kKnockReason), StillnessCause::kKnocked);
  EXPECT_EQ(CauseOfReason("moving: x std 4.1 counts, limit 2.5"), StillnessCause::kMoving);
  EXPECT_EQ(CauseOfReason("drifting: z moved 6.3 counts over the window, limit 3.0"), StillnessCause::kDrifting);
  EXPECT_EQ(CauseOfReason("no stable capture within 60 s: last problem: drifting: z moved 6 counts"),
            StillnessCause::kDrifting);
  EXPECT_EQ(CauseOfReason("wrong face: the reading shows -z up"), StillnessCause::kNone);
}

TEST(CaptureMessages, AKnockDuringTheCaptureIsSaidInWordsAndTheFiguresKeptApart) {
  CaptureSnapshot snap;
  snap.state = CaptureState::kRetrying;
  snap.reason = kKnockReason;
  snap.elapsed_s = 12.0;
  const CaptureMessage m = DescribeCapture(snap, false);
  EXPECT_EQ(m.text, "the bench was knocked: don't touch it; measuring again");
  EXPECT_FALSE(m.waiting);
  EXPECT_EQ(m.detail, kKnockReason);
}

TEST(CaptureMessages, SettlingAfterLettingGoIsAWaitNotAWarning) {
  CaptureSnapshot snap;
  snap.state = CaptureState::kSettling;
  snap.elapsed_s = 1.5;
  snap.stability.judged = true;
  snap.stability.reason = kKnockReason;  // the hand letting go looks like a knock
  CaptureMessage m = DescribeCapture(snap, false);
  EXPECT_EQ(m.text, "still settling after you let go: wait");
  EXPECT_TRUE(m.waiting);
  EXPECT_FALSE(HasStatistics(m.text));
  // Past the normal settling, the cause gets its name.
  snap.elapsed_s = kNormalSettleS + 1.0;
  snap.stability.reason = "moving: x std 12 counts, limit 2.4";
  m = DescribeCapture(snap, false);
  EXPECT_FALSE(m.waiting);
  EXPECT_TRUE(Contains(m.text, "the bench is shaking")) << m.text;
  EXPECT_FALSE(HasStatistics(m.text)) << m.text;
  snap.stability.reason = "drifting: z moved 6.3 counts over the window, limit 3.0";
  m = DescribeCapture(snap, false);
  EXPECT_TRUE(Contains(m.text, "the sensor is drifting")) << m.text;
}

TEST(CaptureMessages, AGiveUpOnStillnessSaysWhyInWords) {
  const std::string reason = "no stable capture within 60 s: last problem: moving: x std 12 counts, limit 2.4";
  const CaptureMessage m = DescribeEnded(reason, 60.0);
  EXPECT_EQ(m.text, "gave up after 60 s: the bench kept shaking");
  EXPECT_EQ(m.detail, reason);
  // Reasons already in words about the bench stay as they are.
  EXPECT_EQ(DescribeEnded("wrong face: -z up", 60.0).text, "wrong face: -z up");
  const std::string silent = "no stable capture within 60 s (wall clock): no samples for 61 s";
  EXPECT_EQ(DescribeEnded(silent, 60.0).text, silent);
}

// Issue 27, item 9: a vibrating bench "gave up after 60 s: the bench kept being knocked" with the
// hint "put the prism with -z up and let go": the hint is about the bench, not the placement.
TEST(CaptureMessages, AGiveUpOnStillnessHintsAtTheBench) {
  const std::string shaking = std::string("no stable capture within 60 s: last problem: ") + kKnockReason;
  EXPECT_EQ(DescribeEnded(shaking, 60.0).text, "gave up after 60 s: the bench kept being knocked or shaken");
  EXPECT_TRUE(Contains(StillnessHint(shaking), "find what shakes or knocks the bench")) << StillnessHint(shaking);
  EXPECT_FALSE(Contains(StillnessHint(shaking), "prism"));
  EXPECT_TRUE(Contains(StillnessHint("no stable capture within 60 s: last problem: drifting: z moved 6 counts"),
                       "warm up"));
  EXPECT_EQ(StillnessHint("wrong face: the reading shows -z up"), "");  // the placement's hint then
}

// ---- the time -------------------------------------------------------------------------------

TEST(TimeEstimate, TheSessionIsTheRemainingStepsAndTheirHandling) {
  const Procedure p = testing::FullProcedure();
  const auto none_done = [](const ProcedureStep&) { return false; };
  double by_hand = 0.0;
  const TimeAllowances a;
  for (const ProcedureStep& s : p.steps) {
    switch (s.kind) {
      case StepKind::kStatic: by_hand += a.place_pose_s + a.settle_s + s.duration_s; break;
      case StepKind::kTurntable: by_hand += a.mount_turntable_s + a.settle_s + s.duration_s; break;
      case StepKind::kLevel: by_hand += a.level_s + 2 * (a.settle_s + s.duration_s); break;
      case StepKind::kRecord: by_hand += a.place_pose_s + a.settle_s + s.duration_s; break;
      default:
        // A pose of a kind defined beside its controller (the repeat) is placed like a static one.
        by_hand += IsStaticPoseStep(s.kind) ? a.place_pose_s + a.settle_s + s.duration_s : a.read_result_s;
        break;
    }
  }
  EXPECT_DOUBLE_EQ(RemainingEstimateS(p, 0, none_done), by_hand);
  // Steps done are not counted; past the end nothing is left.
  const auto statics_done = [](const ProcedureStep& s) { return s.kind == StepKind::kStatic; };
  EXPECT_LT(RemainingEstimateS(p, 0, statics_done), by_hand);
  EXPECT_DOUBLE_EQ(RemainingEstimateS(p, static_cast<int>(p.steps.size()), none_done), 0.0);
  EXPECT_EQ(FormatEstimate(14.2 * 60), "about 14 min");
  EXPECT_EQ(FormatEstimate(42), "about 40 s");
  EXPECT_EQ(CaptureTimeText(10, 3.6, 52.6, 840),
            "4 s left of this capture; gives up in 53 s; session: about 14 min left (estimate)");
  EXPECT_EQ(CaptureTimeText(10, kNaN, 60, kNaN),
            "this capture takes 10 s once the sensor is still; gives up in 60 s");
}

// ---- the engine on the clumsy bench ---------------------------------------------------------

Procedure ShortProcedure() { return testing::ShortFullProcedure(); }

sim::Scenario Clumsy(const std::string& name) {
  return sim::LoadScenario(std::string(ACCELCAL_SOURCE_DIR) + "/scenarios/" + name);
}

// Every view of a whole session, Enter at every question.
std::vector<WizardView> WholeSession(WizardEngine& e) {
  std::vector<WizardView> views;
  for (int i = 0; i < 3000; ++i) {
    for (int p = 0; p < 5000 && testing::Busy(e.View()); ++p) {
      e.Poll(0.0);
      views.push_back(e.View());
    }
    views.push_back(e.View());
    if (views.back().finished) return views;
    e.Handle({IntentKind::kAccept, ""});
  }
  ADD_FAILURE() << "the session did not finish";
  return views;
}

TEST(CaptureFlow, TheKnockIsSaidInWordsTheFiguresOnlyInTheDetail) {
  testing::WizardRig rig(ShortProcedure(), Clumsy("clumsy_bump.toml"));
  const std::vector<WizardView> views = WholeSession(rig.engine);
  bool knocked = false, waited = false;
  for (const WizardView& v : views) {
    if (v.screen != WizardScreen::kCapturing || v.record) continue;
    EXPECT_FALSE(HasStatistics(v.stability_text)) << v.stability_text;
    EXPECT_FALSE(Contains(v.prompt, "sigma") || Contains(v.prompt, " std ")) << v.prompt;
    EXPECT_TRUE(v.problem.empty()) << "a retry is not a failure: " << v.problem;
    if (v.stability_text == "the bench was knocked: don't touch it; measuring again") {
      knocked = true;
      EXPECT_TRUE(Contains(v.detail, "spike: ")) << v.detail;
      EXPECT_FALSE(v.waiting);
    }
    if (v.waiting) {
      waited = true;
      EXPECT_TRUE(v.stability_text == "still settling after you let go: wait" ||
                  v.stability_text == "waiting for the table to turn steadily")
          << v.stability_text;
    }
  }
  EXPECT_TRUE(knocked) << "the knock was never said";
  EXPECT_TRUE(waited) << "the settling was never said as a wait";
  EXPECT_EQ(views.back().verdict, "PASS");
}

TEST(CaptureFlow, EveryCaptureScreenSaysItsTimeAndTheSessions) {
  testing::WizardRig rig(ShortProcedure(), Clumsy("clumsy_bump.toml"));
  const std::vector<WizardView> views = WholeSession(rig.engine);
  int capturing_views = 0;
  double last_left_s = kNaN;
  double first_session_s = kNaN;
  for (const WizardView& v : views) {
    if (!v.finished && v.time_text != LastStepTimeText()) {
      EXPECT_TRUE(Contains(v.time_text, "(estimate)")) << v.step_title << ": " << v.prompt;
      if (std::isnan(first_session_s)) first_session_s = v.session_left_s;
    }
    if (v.screen != WizardScreen::kCapturing || v.record || std::isnan(v.give_up_in_s)) continue;
    EXPECT_GE(v.give_up_in_s, 0.0);
    EXPECT_LE(v.give_up_in_s, 60.0);
    EXPECT_TRUE(Contains(v.time_text, "gives up in ")) << v.time_text;
    if (std::isfinite(v.capture_left_s)) {
      ++capturing_views;
      EXPECT_GE(v.capture_left_s, 0.0);
      EXPECT_LE(v.capture_left_s, 3.0);
      EXPECT_TRUE(Contains(v.time_text, "s left of this capture")) << v.time_text;
      EXPECT_TRUE(Contains(v.prompt, " s left")) << v.prompt;  // not only a percentage
      last_left_s = v.capture_left_s;
    }
  }
  EXPECT_GT(capturing_views, 10);
  EXPECT_TRUE(std::isfinite(last_left_s));
  // The estimate at the welcome covers the whole procedure: 10 static steps, 9 turntable runs...
  EXPECT_GT(first_session_s, 10 * 60.0);
  EXPECT_LT(first_session_s, 40 * 60.0);
}

// Issue 35: the report, the last step, said "session: about 20 s left (estimate)" (its reading
// allowance) at the end of a finished session, in line mode and in the TUI alike (both show the
// view's time_text). The last step's result says the session ends; every earlier screen keeps
// its estimate.
TEST(CaptureFlow, TheLastStepSaysTheSessionEndsNotThatTimeIsLeft) {
  testing::WizardRig rig(ShortProcedure(), Clumsy("clumsy_bump.toml"));
  const std::vector<WizardView> views = WholeSession(rig.engine);
  ASSERT_TRUE(views.back().finished);
  const WizardView* last_timed = nullptr;
  for (const WizardView& v : views)
    if (!v.time_text.empty()) last_timed = &v;
  ASSERT_NE(last_timed, nullptr);
  EXPECT_EQ(last_timed->step_title, ShortProcedure().steps.back().title);
  EXPECT_EQ(last_timed->time_text, LastStepTimeText());
  EXPECT_FALSE(Contains(last_timed->time_text, "left")) << last_timed->time_text;
  EXPECT_EQ(last_timed->session_left_s, 0.0);
  // Only the last step says so: the fit and the diagnosis before it still count the report.
  int ending = 0;
  for (const WizardView& v : views) ending += v.time_text == LastStepTimeText();
  EXPECT_GT(ending, 0);
  for (const WizardView& v : views) {
    if (v.time_text == LastStepTimeText()) {
      EXPECT_EQ(v.step_title, last_timed->step_title);
    }
  }
}

TEST(CaptureFlow, AnAcceptedCaptureIsConfirmedWithItsFiguresUntilTheNextKey) {
  testing::WizardRig rig(ShortProcedure(), Clumsy("clumsy_bump.toml"));
  testing::AcceptUntil(rig.engine, [](const WizardView& v) { return !v.notice.empty(); });
  const WizardView v = rig.engine.View();
  // The first capture is +z up: 3 s, |a| near g by the datasheet's model (the default bench's
  // z bias is 15 counts above the datasheet's: 0.4 m/s^2 more), the sensor's own noise.
  EXPECT_EQ(v.notice.rfind("+z up done: 3.0 s, |a| ~", 0), 0u) << v.notice;
  const double a_mps2 = std::stod(v.notice.substr(v.notice.find('~') + 1));
  EXPECT_NEAR(a_mps2, 9.81, 0.5) << v.notice;
  EXPECT_TRUE(Contains(v.notice, " m/s^2 by the datasheet, noise 1.")) << v.notice;
  EXPECT_TRUE(Contains(v.notice, "noise 1.")) << v.notice;
  EXPECT_EQ(v.step_title.find("+z"), std::string::npos) << "shown on the next step: " << v.step_title;
  rig.engine.Handle({IntentKind::kAccept, ""});
  EXPECT_TRUE(rig.engine.View().notice.empty());
}

TEST(CaptureFlow, TheFinalScreenSaysTheVerdictTheNumbersAndTheFiles) {
  testing::WizardRig rig(ShortProcedure(), Clumsy("clumsy_bump.toml"));
  const std::vector<WizardView> views = WholeSession(rig.engine);
  const WizardView& v = views.back();
  ASSERT_TRUE(v.finished);
  EXPECT_EQ(v.verdict, "PASS");
  EXPECT_EQ(v.prompt, "Calibration complete.");  // the verdict once, in the lines
  ASSERT_FALSE(v.lines.empty());
  EXPECT_EQ(v.lines.front(), "Verdict: PASS");
  const std::string all = [&] {
    std::string s;
    for (const std::string& l : v.lines) s += l + "\n";
    return s;
  }();
  EXPECT_TRUE(Contains(all, "bias (counts)        x 205")) << all;
  EXPECT_TRUE(Contains(all, "scale (counts/m/s^2) x 34.")) << all;
  EXPECT_TRUE(Contains(all, "misalignment (mrad)  yz ")) << all;
  EXPECT_TRUE(Contains(all, "residual RMS")) << all;
  EXPECT_TRUE(Contains(all, " +- ")) << all;
  for (const std::string& l : v.lines) EXPECT_LE(l.size(), 80u) << l;
}

TEST(CaptureFlow, AFailedLimitIsNamedOnTheFinalScreen) {
  Procedure p = ShortProcedure();
  p.limits.max_bias_U_counts = 1e-6;  // no bench meets it
  testing::WizardRig rig(p, Clumsy("clumsy_bump.toml"));
  const WizardView v = WholeSession(rig.engine).back();
  EXPECT_EQ(v.verdict, "FAIL");
  ASSERT_GE(v.lines.size(), 2u);
  EXPECT_EQ(v.lines[0], "Verdict: FAIL");
  EXPECT_EQ(v.lines[1].rfind("  limit failed: ", 0), 0u) << v.lines[1];
}

// Reproduces a defect: a finished session opened again said only "Calibration complete.", with
// no verdict and no numbers.
TEST(CaptureFlow, AFinishedSessionOpenedAgainShowsItsSummary) {
  std::shared_ptr<SessionJournal> journal(MakeMemoryJournal());
  std::vector<std::string> first_lines;
  {
    testing::WizardRig rig(ShortProcedure(), Clumsy("clumsy_bump.toml"), journal);
    const WizardView last = WholeSession(rig.engine).back();
    ASSERT_EQ(last.verdict, "PASS");
    first_lines = last.lines;
  }
  testing::WizardRig again(ShortProcedure(), Clumsy("clumsy_bump.toml"), journal);
  // First the offer to refit it with new inputs (issue 27, item 5), over the same summary.
  const WizardView offer = again.engine.View();
  ASSERT_FALSE(offer.finished);
  ASSERT_TRUE(offer.input.has_value());
  EXPECT_EQ(offer.input->key, "refit");
  EXPECT_EQ(offer.verdict, "PASS");
  EXPECT_EQ(offer.lines, first_lines);
  again.engine.Handle({IntentKind::kAccept, ""});  // Enter: leave it as it is
  const WizardView v = again.engine.View();
  ASSERT_TRUE(v.finished);
  EXPECT_TRUE(again.engine.completed());
  EXPECT_EQ(v.verdict, "PASS");
  EXPECT_EQ(v.prompt, "Calibration complete (in an earlier run): nothing left to do.");
  EXPECT_EQ(v.lines, first_lines);  // the same verdict and numbers, computed from the journal
  EXPECT_EQ(journal->ResultCount(), 1);
}

// ---- line mode ------------------------------------------------------------------------------

TEST(CaptureFlow, LineModeSaysTheWordsTheDetailTheTimeTheConfirmationAndTheVerdict) {
  testing::WizardRig rig(ShortProcedure(), Clumsy("clumsy_bump.toml"));
  std::istringstream in(std::string(300, '\n'));
  std::ostringstream out;
  ASSERT_EQ(ui::RunLineMode(rig.engine, in, out), 0);
  const std::string text = out.str();
  const std::string tail = text.substr(text.size() > 3000 ? text.size() - 3000 : 0);
  EXPECT_TRUE(Contains(text, "): the bench was knocked: don't touch it; measuring again\n")) << tail;
  EXPECT_TRUE(Contains(text, "    detail: ")) << tail;
  EXPECT_TRUE(Contains(text, "spike: ")) << tail;
  EXPECT_TRUE(Contains(text, "): still settling after you let go: wait\n")) << tail;
  EXPECT_TRUE(Contains(text, "s left of this capture; gives up in ")) << tail;
  EXPECT_TRUE(Contains(text, "(estimate)")) << tail;
  // Issue 35: its last time line is the last step's, and says the session ends.
  const std::string last_time = text.substr(text.rfind("time: "));
  EXPECT_EQ(last_time.substr(0, last_time.find('\n')), "time: " + LastStepTimeText()) << tail;
  EXPECT_TRUE(Contains(text, "\n  +z up done: 3.0 s, |a| ~")) << tail;
  EXPECT_TRUE(Contains(text, "  Verdict: PASS\n")) << tail;
  // The final summary says the verdict once: its prompt does not repeat it.
  const std::string summary = text.substr(text.rfind("  Verdict: PASS\n"));
  EXPECT_TRUE(Contains(summary, "\nCalibration complete.\n")) << summary;
  EXPECT_FALSE(Contains(summary, "complete: PASS")) << summary;
  EXPECT_TRUE(Contains(text, "  bias (counts)")) << tail;
  // The statistics never on a main line: every line with "sigma" is a detail line; and a normal
  // wait (settling after letting go) prints none (issue 27, item 9: "z std 2.9e+02 ... 225.8
  // sigma" under every placement).
  std::istringstream lines(text);
  std::string previous;
  for (std::string line; std::getline(lines, line); previous = line) {
    if (Contains(line, "sigma) at t =")) {
      EXPECT_EQ(line.rfind("    detail: ", 0), 0u) << line;
    }
    if (Contains(previous, "still settling after you let go: wait")) {
      EXPECT_NE(line.rfind("    detail: ", 0), 0u) << previous << "\n" << line;
    }
  }
}

}  // namespace
}  // namespace accelcal
