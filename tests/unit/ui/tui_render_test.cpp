// The TUI's drawing: fixed-size renders compared with golden text (tests/data/tui/*.txt).
// ACCELCAL_UPDATE_GOLDEN=1 rewrites the golden files from the current renderer (review the diff).
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "test_support.h"
#include "tui/render.h"
#include "tui_golden.h"
#include "tui_test_views.h"

namespace accelcal::ui {
namespace {

using accelcal::testing::Contains;

TEST(TuiRender, WelcomeWithInput80x24) {
  ExpectGolden("welcome_80x24", Render(accelcal::testing::WelcomeView(), {"Ann", 0}, 80, 24));
}

TEST(TuiRender, StaticPose80x24) {
  ExpectGolden("static_pose_80x24",
               Render(accelcal::testing::StaticPoseView(), {}, 80, 24));
}

TEST(TuiRender, StaticPose60x20) {
  ExpectGolden("static_pose_60x20",
               Render(accelcal::testing::StaticPoseView(), {}, 60, 20));
}

TEST(TuiRender, Capturing80x24) {
  ExpectGolden("capturing_80x24", Render(accelcal::testing::CapturingView(), {}, 80, 24));
}

TEST(TuiRender, Failure80x24) {
  ExpectGolden("failure_80x24", Render(accelcal::testing::FailureView(), {}, 80, 24));
}

TEST(TuiRender, ReportScrolled80x24) {
  ExpectGolden("report_80x24", Render(accelcal::testing::ReportView(), {"", 5}, 80, 24));
}

TEST(TuiRender, Turntable120x40) {
  ExpectGolden("turntable_120x40",
               Render(accelcal::testing::TurntableView(), {"12o", 0}, 120, 40));
}

TEST(TuiRender, Tiny40x12) {
  ExpectGolden("static_pose_40x12",
               Render(accelcal::testing::StaticPoseView(), {}, 40, 12));
}

TEST(TuiRender, Recording80x24) {
  ExpectGolden("recording_80x24", Render(accelcal::testing::RecordingView(), {}, 80, 24));
}

TEST(TuiRender, RecordingWithAllan120x40) {
  ExpectGolden("recording_allan_120x40",
               Render(accelcal::testing::RecordingWithAllanView(), {}, 120, 40));
}

TEST(TuiRender, RecordingSaysWhenTheAllanCurveIsEmpty) {
  const std::string text = Render(accelcal::testing::RecordingView(), {}, 120, 40).Text();
  EXPECT_TRUE(Contains(text, "Allan curve: waiting for data")) << text;
  EXPECT_TRUE(Contains(text, "03:12:05 of 12:00:00")) << text;
  EXPECT_TRUE(Contains(text, "08:47:55 to go")) << text;  // 43200 - 11525 s
  EXPECT_TRUE(Contains(text, "gaps 1 (42 s)")) << text;
  EXPECT_TRUE(Contains(text, "[WARN] moved 1 time")) << text;
}

TEST(TuiRender, DriftPlotRisesWithTheWarmUp) {
  // x warms up by 0.8 counts: its trace starts on the plot's lowest row and ends on its top row.
  const ScreenModel s = Render(accelcal::testing::RecordingView(), {}, 120, 40);
  int x_top = -1;
  for (int r = 0; r < s.height(); ++r)
    if (s.Row(r).rfind("x+", 0) == 0) x_top = r;
  ASSERT_GE(x_top, 0) << s.Text();
  const int first_col = 8;  // kPlotLabelWidth
  const int last_col = first_col + static_cast<int>(11525.0 / 43200.0 * (120 - 8));
  int first_row = -1, last_row = -1;
  for (int r = x_top; r < x_top + 6; ++r) {
    if (s.CharAt(r, first_col) != ' ') first_row = r;
    if (s.CharAt(r, last_col) != ' ' && s.CharAt(r, last_col) != '|') last_row = r;
  }
  EXPECT_EQ(first_row, x_top + 5) << s.Text();
  EXPECT_EQ(last_row, x_top) << s.Text();
}

TEST(TuiRender, NaNDrawnAsDashes) {
  const std::string text = Render(accelcal::testing::FailureView(), {}, 80, 24).Text();
  EXPECT_TRUE(Contains(text, "x     --  y     --  z     --")) << text;
  EXPECT_FALSE(Contains(text, "nan")) << text;
}

TEST(TuiRender, MeaningDoesNotDependOnColour) {
  EXPECT_TRUE(Contains(Render(accelcal::testing::StaticPoseView(), {}, 80, 24).Text(), "[ OK ]"));
  EXPECT_TRUE(Contains(Render(accelcal::testing::CapturingView(), {}, 80, 24).Text(), "[WARN]"));
  const std::string failure = Render(accelcal::testing::FailureView(), {}, 80, 24).Text();
  EXPECT_TRUE(Contains(failure, "[FAIL]"));
  EXPECT_TRUE(Contains(failure, "[HINT]"));
}

TEST(TuiRender, RolesMarkFailureAndTitle) {
  const ScreenModel s = Render(accelcal::testing::FailureView(), {}, 80, 24);
  EXPECT_EQ(s.RoleAt(0, 0), Role::kTitle);
  bool fail_seen = false;
  for (int r = 0; r < s.height(); ++r) {
    if (s.Row(r).rfind("[FAIL]", 0) == 0) fail_seen = s.RoleAt(r, 0) == Role::kFail;
  }
  EXPECT_TRUE(fail_seen);
}

TEST(TuiRender, KeysAndHeaderSurviveEverySize) {
  const WizardView views[] = {
      accelcal::testing::WelcomeView(), accelcal::testing::StaticPoseView(),
      accelcal::testing::CapturingView(), accelcal::testing::FailureView(),
      accelcal::testing::ReportView(), accelcal::testing::TurntableView(),
      accelcal::testing::RecordingView(), accelcal::testing::RecordingWithAllanView()};
  for (const WizardView& view : views) {
    for (int w = 0; w <= 130; w += 7) {
      for (int h = 0; h <= 45; ++h) {
        const ScreenModel s = Render(view, {"typed", 99}, w, h);
        ASSERT_EQ(s.width(), w);
        ASSERT_EQ(s.height(), h);
        if (w >= 12 && h >= 2) {
          EXPECT_EQ(s.Row(0).substr(0, 5), " Step") << w << "x" << h;
          // The quit key comes first: q, or Ctrl-X in a text field (where q is typed).
          EXPECT_TRUE(s.Row(h - 1).find('q') != std::string::npos ||
                      s.Row(h - 1).find("Ctrl-X") != std::string::npos ||
                      s.Row(h - 1).find("any") != std::string::npos)
              << w << "x" << h << "\n" << s.Text();
        }
      }
    }
  }
}

}  // namespace
}  // namespace accelcal::ui
