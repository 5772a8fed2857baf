// The TUI's keys and loop without a terminal: key -> intent in each state, and the loop run
// against a scripted driver and a fake terminal.
#include <deque>
#include <vector>

#include <gtest/gtest.h>

#include "tui/keys.h"
#include "tui/tui_loop.h"
#include "tui_test_views.h"

namespace accelcal::ui {
namespace {

std::optional<IntentKind> KindOf(const KeyOutcome& o) {
  if (!o.intent) return std::nullopt;
  return o.intent->kind;
}

TEST(TuiKeys, CommandKeysWhenNoValueIsAsked) {
  const WizardView view = accelcal::testing::StaticPoseView();
  EditState state;
  EXPECT_EQ(KindOf(HandleKey(view, state, kKeyEnter)), IntentKind::kAccept);
  EXPECT_EQ(KindOf(HandleKey(view, state, 'r')), IntentKind::kRetry);
  EXPECT_EQ(KindOf(HandleKey(view, state, 's')), IntentKind::kSkip);
  EXPECT_EQ(KindOf(HandleKey(view, state, 'b')), IntentKind::kBack);
  EXPECT_EQ(KindOf(HandleKey(view, state, 'n')), IntentKind::kAnswerNo);
  EXPECT_EQ(KindOf(HandleKey(view, state, 'q')), IntentKind::kQuit);
  EXPECT_EQ(KindOf(HandleKey(view, state, 'Q')), IntentKind::kQuit);
  EXPECT_EQ(HandleKey(view, state, 'x').result, KeyResult::kIgnored);
  EXPECT_EQ(HandleKey(view, state, kKeyNone).result, KeyResult::kIgnored);
  EXPECT_EQ(HandleKey(view, state, kKeyResize).result, KeyResult::kRedraw);
}

TEST(TuiKeys, TypingAnAnswer) {
  const WizardView view = accelcal::testing::WelcomeView();
  EditState state;
  for (int key : {'r', 's', 'b', 'X'}) {
    EXPECT_EQ(HandleKey(view, state, key).result, KeyResult::kRedraw);
  }
  EXPECT_EQ(state.text, "rsbX");
  HandleKey(view, state, kKeyBackspace);
  EXPECT_EQ(state.text, "rsb");
  // q is a letter of the answer while there is one.
  HandleKey(view, state, 'q');
  EXPECT_EQ(state.text, "rsbq");
  const KeyOutcome submit = HandleKey(view, state, kKeyEnter);
  ASSERT_EQ(KindOf(submit), IntentKind::kSubmitText);
  EXPECT_EQ(submit.intent->text, "rsbq");
  EXPECT_TRUE(state.text.empty());
}

// Issue 15: in a text field q, s and b were typed (or q quit only on an empty answer) while the
// key bar offered them. Every letter is now typed; the navigation has keys that cannot be typed.
TEST(TuiKeys, EmptyAnswerTakesTheDefaultAndLettersAreTyped) {
  const WizardView view = accelcal::testing::WelcomeView();
  EditState state;
  const KeyOutcome submit = HandleKey(view, state, kKeyEnter);
  ASSERT_EQ(KindOf(submit), IntentKind::kSubmitText);
  EXPECT_EQ(submit.intent->text, "");
  HandleKey(view, state, 'a');
  EXPECT_EQ(HandleKey(view, state, kKeyEscape).result, KeyResult::kRedraw);  // clears first
  EXPECT_TRUE(state.text.empty());
  EXPECT_EQ(HandleKey(view, state, 'q').result, KeyResult::kRedraw);  // "quintana" starts so
  EXPECT_EQ(state.text, "q");
}

TEST(TuiKeys, NavigationFromATextFieldByKeysThatCannotBeTyped) {
  const WizardView view = accelcal::testing::TurntableView();
  EditState state;
  EXPECT_EQ(KindOf(HandleKey(view, state, kKeyEscape)), IntentKind::kBack);  // empty answer
  EXPECT_EQ(KindOf(HandleKey(view, state, kKeyCtrlN)), IntentKind::kSkip);
  EXPECT_EQ(KindOf(HandleKey(view, state, kKeyCtrlX)), IntentKind::kQuit);
  for (int key : {'s', 'b', 'q', 'r'}) HandleKey(view, state, key);
  EXPECT_EQ(state.text, "sbqr");
  EXPECT_EQ(KindOf(HandleKey(view, state, kKeyCtrlX)), IntentKind::kQuit);  // with text typed too
}

TEST(TuiKeys, KeyBarNamesTheKeysThatWorkInATextField) {
  EXPECT_EQ(KeyName("s", true), "Ctrl-N");
  EXPECT_EQ(KeyName("b", true), "Esc");
  EXPECT_EQ(KeyName("q", true), "Ctrl-X");
  EXPECT_EQ(KeyName("Enter", true), "Enter");
  EXPECT_EQ(KeyName("r", true), "");  // a letter with no untypable key: not offered
  EXPECT_EQ(KeyName("s", false), "s");
}

// ? and F1 open the help on every screen, a text field included (? is never typed there); the
// next key only closes it.
TEST(TuiKeys, QuestionMarkAndF1OpenTheHelpEverywhere) {
  for (const WizardView& view : {accelcal::testing::TurntableView(), accelcal::testing::StaticPoseView(),
                                 accelcal::testing::WelcomeView()}) {
    for (int key : {int{'?'}, int{kKeyF1}}) {
      EditState state;
      state.text = "12";
      EXPECT_EQ(HandleKey(view, state, key).result, KeyResult::kRedraw);
      EXPECT_TRUE(state.help);
      EXPECT_EQ(state.text, "12");
      const KeyOutcome close = HandleKey(view, state, kKeyEnter);
      EXPECT_EQ(close.result, KeyResult::kRedraw);
      EXPECT_FALSE(close.intent.has_value());
      EXPECT_FALSE(state.help);
    }
  }
}

TEST(TuiKeys, ScrollingIsClampedToTheLines) {
  const WizardView view = accelcal::testing::ReportView();  // 40 lines
  EditState state;
  state.page = 10;
  HandleKey(view, state, kKeyUp);
  EXPECT_EQ(state.scroll, 0);
  HandleKey(view, state, kKeyPageDown);
  EXPECT_EQ(state.scroll, 9);
  HandleKey(view, state, kKeyDown);
  EXPECT_EQ(state.scroll, 10);
  HandleKey(view, state, kKeyEnd);
  EXPECT_EQ(state.scroll, 39);
  HandleKey(view, state, kKeyHome);
  EXPECT_EQ(state.scroll, 0);
}

TEST(TuiKeys, AnyOtherKeyLeavesTheFinalScreen) {
  const WizardView view = accelcal::testing::ReportView();
  EditState state;
  EXPECT_EQ(HandleKey(view, state, kKeyPageDown).result, KeyResult::kRedraw);
  EXPECT_EQ(HandleKey(view, state, kKeyEnter).result, KeyResult::kExit);
  EXPECT_EQ(HandleKey(view, state, 'q').result, KeyResult::kExit);
}

TEST(TuiKeys, NewStepClearsTheAnswerAndScroll) {
  WizardView view = accelcal::testing::WelcomeView();
  EditState state;
  SyncEditState(view, state);
  state.text = "Ann";
  state.scroll = 3;
  SyncEditState(view, state);
  EXPECT_EQ(state.text, "Ann");
  view.step_index = 2;
  SyncEditState(view, state);
  EXPECT_TRUE(state.text.empty());
  EXPECT_EQ(state.scroll, 0);
}

// A driver serving scripted views: each intent advances to the next view.
class ScriptedDriver : public WizardDriver {
 public:
  explicit ScriptedDriver(std::vector<WizardView> views) : views_(std::move(views)) {}
  void Poll(double) override { ++polls; }
  void Handle(const Intent& intent) override {
    intents.push_back(intent);
    if (at_ + 1 < views_.size()) ++at_;
  }
  WizardView View() const override { return views_[at_]; }

  std::vector<Intent> intents;
  int polls = 0;

 private:
  std::vector<WizardView> views_;
  size_t at_ = 0;
};

class FakeTerminal : public TuiTerminal {
 public:
  explicit FakeTerminal(std::deque<int> keys) : keys_(std::move(keys)) {}
  int ReadKey(int) override {
    if (keys_.empty()) return ++idle > 1000 ? int{kKeyCtrlX} : static_cast<int>(kKeyNone);  // never hang a test
    const int key = keys_.front();
    keys_.pop_front();
    if (key == kKeyResize) width = 60;
    return key;
  }
  int Width() const override { return width; }
  int Height() const override { return 24; }
  void Draw(const ScreenModel& screen) override { drawn.push_back(screen); }

  std::vector<ScreenModel> drawn;
  int width = 80;
  int idle = 0;

 private:
  std::deque<int> keys_;
};

TEST(TuiLoop, RunsAScriptedSessionToTheFinalScreen) {
  ScriptedDriver driver({accelcal::testing::WelcomeView(), accelcal::testing::StaticPoseView(),
                         accelcal::testing::CapturingView(), accelcal::testing::ReportView()});
  FakeTerminal terminal({'A', 'n', 'n', kKeyEnter, kKeyNone, kKeyEnter, 'r', kKeyNone,
                         kKeyPageDown, kKeyEnter});
  EXPECT_EQ(RunTuiLoop(driver, terminal), 0);
  ASSERT_EQ(driver.intents.size(), 3u);
  EXPECT_EQ(driver.intents[0].kind, IntentKind::kSubmitText);
  EXPECT_EQ(driver.intents[0].text, "Ann");
  EXPECT_EQ(driver.intents[1].kind, IntentKind::kAccept);
  EXPECT_EQ(driver.intents[2].kind, IntentKind::kRetry);
  EXPECT_GE(driver.polls, 10);
  // Drawn only when the picture changed: typing 3 letters, 3 new views, one scroll, + first.
  EXPECT_EQ(terminal.drawn.size(), 8u);
}

TEST(TuiLoop, QuitSendsTheIntentAndLeaves) {
  ScriptedDriver driver({accelcal::testing::StaticPoseView(), accelcal::testing::ReportView()});
  FakeTerminal terminal({kKeyNone, 'q'});
  EXPECT_EQ(RunTuiLoop(driver, terminal), 0);
  ASSERT_EQ(driver.intents.size(), 1u);
  EXPECT_EQ(driver.intents[0].kind, IntentKind::kQuit);
}

TEST(TuiLoop, ResizeRedrawsAtTheNewSize) {
  ScriptedDriver driver({accelcal::testing::StaticPoseView()});
  FakeTerminal terminal({kKeyNone, kKeyResize, kKeyNone, 'q'});
  RunTuiLoop(driver, terminal);
  ASSERT_EQ(terminal.drawn.size(), 2u);
  EXPECT_EQ(terminal.drawn[0].width(), 80);
  EXPECT_EQ(terminal.drawn[1].width(), 60);
}

TEST(TuiLoop, AnErrorOnTheFinalScreenExitsWithOne) {
  WizardView error = accelcal::testing::StaticPoseView();
  error.screen = WizardScreen::kError;
  error.problem = "The sample source stopped: serial link closed.";
  error.finished = true;
  ScriptedDriver driver({error});
  FakeTerminal terminal({kKeyEnter});
  EXPECT_EQ(RunTuiLoop(driver, terminal), 1);
}

}  // namespace
}  // namespace accelcal::ui
