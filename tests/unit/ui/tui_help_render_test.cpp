// The TUI's key bar in a text field and its help overlay (issue 15): golden screens
// (tests/data/tui/*.txt; ACCELCAL_UPDATE_GOLDEN=1 rewrites them: review the diff) and the
// facts they must show, checked apart from the goldens so that a rewrite cannot hide a lie.
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tui/render.h"
#include "tui_golden.h"
#include "tui_test_views.h"

namespace accelcal::ui {
namespace {

// The radius asked at a turntable step, as the engine offers it (its keys by letter).
WizardView RadiusView() {
  WizardView v = accelcal::testing::BaseView();
  v.screen = WizardScreen::kInput;
  v.step_index = 12;
  v.step_title = "Turntable: x radial, z up, 50 mm";
  v.prompt = "Turntable run with x radial, z up.";
  v.pose_name = "x radial, z up";
  v.input = InputRequest{"radius", "Radius from the spin axis to the sensor (e.g. 120 mm)", "50 mm",
                         ""};
  v.keys = {{"Enter", "accept"}, {"s", "skip"}, {"b", "back"}, {"q", "save and quit"}};
  return v;
}

std::string LastRow(const ScreenModel& screen) { return screen.Row(screen.height() - 1); }

// The screen's text with its line breaks and runs of blanks as one blank (wrapped words join).
std::string Squeezed(const ScreenModel& screen) {
  std::string out;
  for (char c : screen.Text()) {
    const char ch = c == '\n' ? ' ' : c;
    if (ch == ' ' && !out.empty() && out.back() == ' ') continue;
    out += ch;
  }
  return out;
}

TEST(TuiHelpRender, KeyBarInATextFieldOffersOnlyWhatWorks) {
  const ScreenModel screen = Render(RadiusView(), {}, 80, 24);
  const std::string keys = LastRow(screen);
  for (const char* lie : {" s skip", " b back", "q save", " r retry"})
    EXPECT_EQ(keys.find(lie), std::string::npos) << lie << " in: " << keys;
  for (const char* truth : {"Ctrl-X save and quit", "Enter accept", "Esc back", "Ctrl-N skip", "? help"})
    EXPECT_NE(keys.find(truth), std::string::npos) << truth << " not in: " << keys;
  ExpectGolden("radius_input_80x24", screen);
  // With text typed, Esc clears it first, and the bar says so.
  EXPECT_NE(LastRow(Render(RadiusView(), {"300 r", 0}, 80, 24)).find("Esc clear"), std::string::npos);
}

TEST(TuiHelpRender, CommandScreenKeysAreLettersAndHelp) {
  const std::string keys = LastRow(Render(accelcal::testing::StaticPoseView(), {}, 80, 24));
  EXPECT_NE(keys.find("q save and quit"), std::string::npos) << keys;
  EXPECT_NE(keys.find("s skip"), std::string::npos) << keys;
  EXPECT_NE(keys.find("? help"), std::string::npos) << keys;
}

// Reproduces a defect: at 60 columns the bar ended in "? he", the help key cut in its word.
TEST(TuiHelpRender, ANarrowKeyBarKeepsQuitAndHelpWholeAndCutsNoWord) {
  for (int width : {40, 60}) {
    WizardView v = accelcal::testing::StaticPoseView();
    v.keys.push_back({"Enter", "refit (recommended)"});
    const std::string keys = LastRow(Render(v, {}, width, 20));
    EXPECT_EQ(keys.rfind("q save and quit  ? help", 0), 0u) << keys;
    // Every entry shown is whole: the bar ends in an action the view offers, not a cut word.
    std::string trimmed = keys.substr(0, keys.find_last_not_of(' ') + 1);
    bool ends_whole = trimmed.size() >= 6 && trimmed.compare(trimmed.size() - 6, 6, "? help") == 0;
    for (const KeyHint& k : v.keys) {
      for (const std::string& action : {k.action, k.action.substr(0, k.action.find(" ("))}) {
        const std::string entry = k.key + " " + action;
        if (trimmed.size() >= entry.size() &&
            trimmed.compare(trimmed.size() - entry.size(), entry.size(), entry) == 0)
          ends_whole = true;
      }
    }
    EXPECT_TRUE(ends_whole) << width << " columns: " << keys;
  }
}

TEST(TuiHelpRender, HelpOverATextField) {
  RenderState state;
  state.edit_text = "12";
  state.help = true;
  const ScreenModel screen = Render(RadiusView(), state, 80, 24);
  const std::string text = Squeezed(screen);
  EXPECT_NE(text.find("Help: what this step expects"), std::string::npos) << text;
  EXPECT_NE(text.find("spin axis to the sensor"), std::string::npos) << text;
  EXPECT_NE(text.find("Ctrl-N"), std::string::npos) << text;
  EXPECT_NE(text.find("? or F1"), std::string::npos) << text;
  EXPECT_NE(LastRow(screen).find("any key close the help"), std::string::npos);
  ExpectGolden("help_radius_80x24", screen);
}

TEST(TuiHelpRender, HelpOverAPose) {
  RenderState state;
  state.help = true;
  const ScreenModel screen = Render(accelcal::testing::StaticPoseView(), state, 80, 24);
  const std::string text = Squeezed(screen);
  EXPECT_NE(text.find("keep your hands"), std::string::npos) << text;
  EXPECT_NE(screen.Text().find("\n  s "), std::string::npos) << screen.Text();  // a letter here
  ExpectGolden("help_pose_80x24", screen);
}

// A terminal too short for the help: it is cut, the header and the last row stay.
TEST(TuiHelpRender, HelpInATinyTerminal) {
  RenderState state;
  state.help = true;
  const ScreenModel screen = Render(RadiusView(), state, 40, 8);
  EXPECT_NE(screen.Row(0).find("Step 12 of 14"), std::string::npos);
  EXPECT_NE(LastRow(screen).find("any key"), std::string::npos);
}

}  // namespace
}  // namespace accelcal::ui
