// The TUI screens of issue 15's "way back and bench" part, compared with golden text
// (tests/data/tui/*.txt; ACCELCAL_UPDATE_GOLDEN=1 rewrites them: review the diff): a tilted pose
// drawn standing on its corner or edge with the words to set it, the redo's question, the
// leveling's live tilt with the sensor's offset taken out, and the diagnosis in plain words with
// its statistics one key away, wrapped, never cut at the right edge. The words come from the
// engine's own helpers (pose_setting.h, diagnosis_words.h).
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/app/wizard/diagnosis_words.h"
#include "accelcal/app/wizard/pose_setting.h"
#include "tui/keys.h"
#include "tui/prism_drawing.h"
#include "tui/render.h"
#include "tui_golden.h"
#include "tui/text_util.h"
#include "tui_test_views.h"

namespace accelcal::ui {
namespace {

WizardView TiltedView(const Eigen::Vector3d& up, const std::string& pose) {
  WizardView v = accelcal::testing::StaticPoseView();
  v.step_title = pose;
  v.pose_name = pose;
  v.expected_up = up;
  v.prompt = "Set the prism " + PrismSetting(up, pose) + " and let go; press Enter to capture.";
  return v;
}

TEST(TuiWayBack, ATiltedPoseStandsOnItsCornerWithTheWordsToSetIt) {
  const WizardView v = TiltedView(Eigen::Vector3d(1, 1, 1), "tilted +x+y+z");
  EXPECT_EQ(v.prompt,
            "Set the prism on its -X-Y-Z corner (where the -X, -Y and -Z faces meet), the +X+Y+Z corner "
            "straight above it: the +X, +Y and +Z faces each tilted 54.7 deg from level; steady it in a "
            "holder and let go; press Enter to capture.");
  const ScreenModel screen = Render(v, {}, 80, 24);
  EXPECT_EQ(screen.Text().find("+--------+"), std::string::npos);  // not the upright box
  ExpectGolden("tilted_corner_80x24", screen);
}

TEST(TuiWayBack, ATiltedPoseOnAnEdge) {
  const WizardView v = TiltedView(Eigen::Vector3d(1, 0, -1), "tilted +x-z");
  EXPECT_EQ(PrismSetting(Eigen::Vector3d(1, 0, -1), "tilted +x-z"),
            "on its -X+Z edge (where the -X and +Z faces meet), the +X-Z edge straight above it: the +X "
            "and -Z faces each tilted 45.0 deg from level; steady it in a holder");
  ExpectGolden("tilted_edge_60x20", Render(v, {}, 60, 20));
}

TEST(TuiWayBack, DrawingsOfEveryTiltedPoseFitTheirColumn) {
  for (const Eigen::Vector3d& up : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(-1, 1, -1),
                                    Eigen::Vector3d(0, 1, 1), Eigen::Vector3d(1, -1, 0)}) {
    const std::vector<std::string> rows = DrawPose(up, "tilted", false);
    ASSERT_FALSE(rows.empty());
    for (const std::string& row : rows) EXPECT_LE(static_cast<int>(row.size()), kDrawingWidth) << row;
    EXPECT_NE(rows.back().find(UpLabel(-up)), std::string::npos) << rows.back();
    EXPECT_NE(rows.front().find(UpLabel(up) + " up"), std::string::npos) << rows.front();
  }
  EXPECT_EQ(DrawPose(Eigen::Vector3d(1, 1, 1), "", false).back(), "corner -X-Y-Z down");
  EXPECT_EQ(DrawPose(Eigen::Vector3d(1, 0, 1), "", false).back(), "edge -X-Z down");
  EXPECT_EQ(DrawPose(Eigen::Vector3d(0, 0, 1), "", false).back(), "face up: +Z");  // unchanged
}

TEST(TuiWayBack, TheRedoQuestion) {
  WizardView v = accelcal::testing::StaticPoseView();
  v.step_index = 3;
  v.step_title = "+z up";
  v.prompt = "Take '+z up' again? Its capture 1 was accepted. The new capture replaces it once accepted; "
             "the old one stays in the session, marked superseded, out of the fit and the report. Enter "
             "takes it again, b looks further back, n keeps it.";
  v.keys = {{"Enter", "take it again"}, {"b", "further back"}, {"n", "keep it"}, {"q", "save and quit"}};
  ExpectGolden("redo_question_80x24", Render(v, {}, 80, 24));
}

TEST(TuiWayBack, TheLevelingTiltSaysWhetherTheOffsetIsIn) {
  WizardView v = accelcal::testing::StaticPoseView();
  v.screen = WizardScreen::kLevel;
  v.step_index = 2;
  v.step_title = "Level the table";
  v.prompt = "Put the prism on the table with +z up and let go; press Enter to measure the tilt.";
  v.tilt_deg = Eigen::Vector2d(0.02, -0.03);
  v.tilt_note = "sensor's offset (x 0.0, y -1.7 deg) taken out";
  ExpectGolden("level_offset_out_80x24", Render(v, {}, 80, 24));
  v.tilt_deg = Eigen::Vector2d(0.02, -1.71);
  v.tilt_note = "includes the sensor's offset until the reversal";
  EXPECT_NE(Render(v, {}, 80, 24).Text().find("includes the sensor's offset until the reversal"), std::string::npos);
}

AdoptedEffect Effect1(const std::string& name, std::vector<double> p, std::vector<double> sigma) {
  AdoptedEffect e;
  e.name = name;
  e.parameters = std::move(p);
  e.uncertainty = std::move(sigma);
  return e;
}

WizardView DiagnosisView(bool statistics) {
  DiagnosisReport r;
  r.adopted = {Effect1("radius_offset", {0.0030}, {0.0002}),
               Effect1("quadratic_nonlinearity", {0.02, -0.015, 0.01}, {0.001, 0.001, 0.001})};
  FitSummary base, final_fit;
  base.residual_rms_mps2 = 0.0213;
  final_fit.residual_rms_mps2 = 0.0031;
  r.stages = {base, final_fit};
  r.final_fit = final_fit;
  r.noise_rms_mps2 = 0.0029;
  const DiagnosisWords words = DiagnosisInPlainWords(r, 9.80665);
  WizardView v = accelcal::testing::BaseView();
  v.screen = WizardScreen::kDiagnosis;
  v.step_index = 22;
  v.step_count = 23;
  v.step_title = "Diagnosis: effects the model lacks";
  v.prompt = words.prompt;
  v.lines = words.lines;
  if (statistics) {
    // Rows as wide as the diagnosis's tables: once cut at the right edge.
    v.lines = {"Round 1: residual RMS 0.0213 m/s^2, chi2/dof 54.1 (p 0)",
               "  candidate               BIC      AICc     LR p       LOO RMS m/s^2  worst LOO z   outcome",
               "  radius_offset           812.4    790.1    1.2e-40    0.0061         3.1           adopted (best BIC, predicts the left-out captures) END1",
               "  quadratic_nonlinearity  1012.9   995.4    3.3e-21    0.0102         4.4           scored END2"};
  }
  v.keys = {{"Enter", words.recommended_action}, {"n", "keep basic model"},
            {"d", statistics ? "plain words" : "statistics"}, {"s", "skip"}, {"b", "back"},
            {"q", "save and quit"}};
  return v;
}

TEST(TuiWayBack, TheDiagnosisInPlainWords) {
  const ScreenModel screen = Render(DiagnosisView(false), {}, 80, 24);
  EXPECT_EQ(screen.Text().find("BIC"), std::string::npos);
  ExpectGolden("diagnosis_plain_80x24", screen);
}

TEST(TuiWayBack, TheDiagnosisStatisticsAreWrappedNotCut) {
  const ScreenModel screen = Render(DiagnosisView(true), {}, 80, 24);
  const std::string text = screen.Text();
  EXPECT_NE(text.find("END1"), std::string::npos) << text;
  EXPECT_NE(text.find("END2"), std::string::npos) << text;
  ExpectGolden("diagnosis_statistics_80x24", screen);
  EditState state;
  const KeyOutcome d = HandleKey(DiagnosisView(false), state, 'd');
  ASSERT_TRUE(d.intent.has_value());
  EXPECT_EQ(d.intent->kind, IntentKind::kDetails);
}

TEST(TuiWayBack, WrapLinesKeepsTheIndentAndEveryWord) {
  const std::vector<std::string> out = WrapLines({"short", "  one two three four five six"}, 14);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0], "short");
  EXPECT_EQ(out[1], "  one two");
  EXPECT_EQ(out[2], "    three four");
  EXPECT_EQ(out[3], "    five six");
}

}  // namespace
}  // namespace accelcal::ui
