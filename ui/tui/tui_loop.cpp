#include "tui/tui_loop.h"

#include <algorithm>

#include "tui/keys.h"
#include "tui/render.h"

namespace accelcal::ui {

namespace {

int ExitStatus(const WizardView& view) { return view.screen == WizardScreen::kError ? 1 : 0; }

}  // namespace

bool NeedsRedraw(const std::optional<ScreenModel>& drawn, const ScreenModel& next) {
  return !drawn || !(*drawn == next);
}

int RunTuiLoop(WizardDriver& driver, TuiTerminal& terminal) {
  EditState edit;
  std::optional<ScreenModel> drawn;
  for (;;) {
    driver.Poll(kPollSeconds);
    const WizardView view = driver.View();
    SyncEditState(view, edit);
    const int width = terminal.Width();
    const int height = terminal.Height();
    edit.page = std::max(height / 2, 1);
    edit.width = width;
    ScreenModel screen =
        Render(view, RenderState{edit.text, edit.scroll, edit.help, edit.details}, width, height);
    if (NeedsRedraw(drawn, screen)) {
      terminal.Draw(screen);
      drawn = std::move(screen);
    }
    const int key = terminal.ReadKey(kKeyTimeoutMs);
    const KeyOutcome outcome = HandleKey(view, edit, key);
    switch (outcome.result) {
      case KeyResult::kIgnored:
      case KeyResult::kRedraw:  // the next render differs, or (resize) has another size
        break;
      case KeyResult::kExit:
        return ExitStatus(view);
      case KeyResult::kIntent:
        driver.Handle(*outcome.intent);
        if (outcome.intent->kind == IntentKind::kQuit) return 0;  // the engine saved
        break;
    }
  }
}

}  // namespace accelcal::ui
