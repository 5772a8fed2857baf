// Issue 15 in the TUI: the capture flow's screens as golden text (tests/data/tui/flow_*.txt;
// ACCELCAL_UPDATE_GOLDEN=1 rewrites them, review the diff), the `d` key that shows the figures,
// and what the TUI leaves on the terminal when it exits.
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "test_support.h"
#include "tui/exit_summary.h"
#include "tui/keys.h"
#include "tui/render.h"
#include "tui_golden.h"
#include "tui_test_views.h"

namespace accelcal::ui {
namespace {

using accelcal::testing::Contains;

constexpr const char* kKnock =
    "moving: x std 1.2e+02 counts, limit 2.2; drifting: x moved 4e+02 counts over the window, "
    "limit 3; spike: z jumped -231 counts (135.1 sigma) at t = 9.64 s";

// Settling just after the prism was let go: a wait.
WizardView SettlingView() {
  WizardView v = testing::StaticPoseView();
  v.screen = WizardScreen::kCapturing;
  v.prompt = "settling +z up (attempt 1): still settling after you let go: wait";
  v.stability = 3.2;
  v.waiting = true;
  v.stability_text = "still settling after you let go: wait";
  v.detail = "moving: x std 5.1 counts, limit 2.2";
  v.progress = 0.0;
  v.give_up_in_s = 58.4;
  v.time_text = "this capture takes 10 s once the sensor is still; gives up in 59 s; session: about 14 "
                "min left (estimate)";
  v.keys = {{"r", "retry"}, {"s", "skip"}, {"b", "back"}, {"q", "save and quit"}};
  return v;
}

// A knock during the capture of the tilted pose.
WizardView KnockedView() {
  WizardView v = SettlingView();
  v.step_title = "Prism: tilted +x+y+z (pose 7 of 9)";
  v.expected_up = Eigen::Vector3d(1, 1, 1).normalized();
  v.pose_name = "tilted +x+y+z";
  v.prompt = "retrying tilted +x+y+z (attempt 2): the bench was knocked: don't touch it; measuring again";
  v.stability = 22.5;
  v.waiting = false;
  v.stability_text = "the bench was knocked: don't touch it; measuring again";
  v.detail = kKnock;
  v.give_up_in_s = 47.0;
  v.time_text = "this capture takes 10 s once the sensor is still; gives up in 47 s; session: about 11 "
                "min left (estimate)";
  return v;
}

WizardView CapturingWithTimeView() {
  WizardView v = SettlingView();
  v.prompt = "capturing +z up (attempt 1): 62 %, 4 s left; keep hands off the bench";
  v.stability = 0.4;
  v.waiting = false;
  v.stability_text = "still";
  v.detail.clear();
  v.progress = 0.62;
  v.capture_left_s = 3.8;
  v.time_text = "4 s left of this capture; gives up in 51 s; session: about 14 min left (estimate)";
  return v;
}

// The next pose's screen, with the last one confirmed.
WizardView ConfirmedView() {
  WizardView v = testing::StaticPoseView();
  v.step_title = "Prism: -z up (pose 4 of 9)";
  v.expected_up = Eigen::Vector3d(0, 0, -1);
  v.pose_name = "-z up";
  v.prompt = "Put the prism on the table with -z up and let go; press Enter to capture.";
  v.notice = "+z up done: 10.0 s, |a| ~10.12 m/s^2 by the datasheet, noise 1.6 counts";
  v.time_text = "this capture takes 10 s once the sensor is still (gives up after 60 s); session: about "
                "13 min left (estimate)";
  return v;
}

WizardView VerdictView() {
  WizardView v = testing::BaseView();
  v.step_index = 23;
  v.step_count = 23;
  v.screen = WizardScreen::kDone;
  v.step_title = "Done";
  v.finished = true;
  v.verdict = "PASS";
  v.prompt = "Calibration complete.";
  v.lines = {
      "Verdict: PASS",
      "bias (counts)        x 2051.31 +- 0.12  y 2039.58 +- 0.12  z 2062.83 +- 0.13",
      "scale (counts/m/s^2) x 34.6197 +- 0.0021 y 35.0710 +- 0.0020 z 34.4105 +- 0.0022",
      "misalignment (mrad)  yz 4.213 +- 0.061  zy -3.088 +- 0.058  zx 5.690 +- 0.060",
      "residual RMS         0.00211 m/s^2 over 18 captures (noise alone: 0.00172)",
      "Report: /home/tech/.local/share/accelcal/sessions/bench.db.report.html",
      "Report: /home/tech/.local/share/accelcal/sessions/bench.db.report.txt"};
  v.keys.clear();
  v.status.clear();
  return v;
}

TEST(TuiCaptureFlow, SettlingIsAWait80x24) {
  const ScreenModel s = Render(SettlingView(), {}, 80, 24);
  ExpectGolden("flow_settling_80x24", s);
  EXPECT_TRUE(Contains(s.Text(), "[WAIT]"));
  EXPECT_FALSE(Contains(s.Text(), "[WARN]"));
  EXPECT_FALSE(Contains(s.Text(), "std 5.1")) << "the figures are one key away";
}

TEST(TuiCaptureFlow, KnockInWordsFiguresOneKeyAway100x30) {
  const WizardView view = KnockedView();
  const ScreenModel hidden = Render(view, {}, 100, 30);
  ExpectGolden("flow_knocked_100x30", hidden);
  EXPECT_FALSE(Contains(hidden.Text(), "sigma"));
  EXPECT_TRUE(Contains(hidden.Text(), "d figures"));
  // `d` shows them, `d` again hides them.
  EditState edit;
  EXPECT_EQ(HandleKey(view, edit, 'd').result, KeyResult::kRedraw);
  ASSERT_TRUE(edit.details);
  const ScreenModel shown = Render(view, {.edit_text = "", .scroll = 0, .details = edit.details}, 100, 30);
  ExpectGolden("flow_knocked_details_100x30", shown);
  EXPECT_TRUE(Contains(shown.Text(), "135.1 sigma"));
  HandleKey(view, edit, 'd');
  EXPECT_FALSE(edit.details);
  // It holds across screens, even one without figures (a key pressed as the screen changed);
  // in a text field `d` is typed.
  EXPECT_EQ(HandleKey(testing::StaticPoseView(), edit, 'd').result, KeyResult::kRedraw);
  EXPECT_TRUE(edit.details);
  EditState typing;
  HandleKey(testing::WelcomeView(), typing, 'd');
  EXPECT_EQ(typing.text, "d");
  EXPECT_FALSE(typing.details);
}

TEST(TuiCaptureFlow, CapturingSaysItsSecondsLeft80x24) {
  const ScreenModel s = Render(CapturingWithTimeView(), {}, 80, 24);
  ExpectGolden("flow_capturing_80x24", s);
  EXPECT_TRUE(Contains(s.Text(), "4 s left of this capture"));
  EXPECT_TRUE(Contains(s.Text(), "gives up in 51 s"));
}

TEST(TuiCaptureFlow, TheAcceptedCaptureIsConfirmedOnTheNextScreen80x24) {
  const ScreenModel s = Render(ConfirmedView(), {}, 80, 24);
  ExpectGolden("flow_confirmed_80x24", s);
  EXPECT_TRUE(Contains(s.Text(), "[DONE] +z up done: 10.0 s"));
}

TEST(TuiCaptureFlow, TheFinalScreenShowsTheVerdict100x30) {
  const ScreenModel s = Render(VerdictView(), {}, 100, 30);
  ExpectGolden("flow_verdict_100x30", s);
  EXPECT_EQ(s.RoleAt(2, 0), Role::kPass);
  EXPECT_TRUE(Contains(s.Text(), "[PASS] Verdict: PASS"));
  // Said once: the summary's own "Verdict: PASS" line is the block above, not repeated below.
  const std::string text = s.Text();
  size_t said = 0;
  for (size_t at = text.find("PASS"); at != std::string::npos; at = text.find("PASS", at + 1)) ++said;
  EXPECT_EQ(said, 2u) << text;  // "[PASS] Verdict: PASS" and nowhere else
  EXPECT_TRUE(Contains(s.Text(), "bench.db.report.html"));
}

TEST(TuiCaptureFlow, AFailingVerdictIsMarkedAsAFailure) {
  WizardView v = VerdictView();
  v.verdict = "FAIL";
  const ScreenModel s = Render(v, {}, 100, 30);
  EXPECT_TRUE(Contains(s.Text(), "[FAIL] Verdict: FAIL"));
  EXPECT_EQ(s.RoleAt(2, 0), Role::kFail);
}

TEST(TuiExitSummary, TheVerdictAndNumbersStayOnTheTerminal) {
  std::ostringstream out;
  PrintExitSummary(VerdictView(), out);
  EXPECT_EQ(out.str().rfind("Calibration complete.\n  Verdict: PASS\n  bias (counts)", 0), 0u) << out.str();
  EXPECT_TRUE(Contains(out.str(), "  Report: /home/tech/")) << out.str();
}

TEST(TuiExitSummary, AfterQuitItSaysHowToResume) {
  WizardView v = testing::BaseView();
  v.screen = WizardScreen::kDone;
  v.finished = true;
  v.prompt = "Saved. Everything accepted is in session s.db; run the wizard on it again to resume.";
  v.lines = {"a fit line that is not a summary"};
  std::ostringstream out;
  PrintExitSummary(v, out);
  EXPECT_EQ(out.str(), v.prompt + "\n");
}

}  // namespace
}  // namespace accelcal::ui
