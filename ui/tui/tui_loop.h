// The TUI's one loop (docs/STYLE.md: htop's ScreenManager_run): poll the driver, draw its view when
// the picture changed, read a key with a short timeout, act on the key's result, until the
// final screen is left or q was sent. The terminal is an interface so tests run the loop
// against a fake one.
#pragma once

#include <optional>

#include "accelcal/app/wizard/wizard_driver.h"
#include "tui/screen_model.h"

namespace accelcal::ui {

class TuiTerminal {
 public:
  virtual ~TuiTerminal() = default;
  // The next key (ui/tui/keys.h codes or printable ASCII), or kKeyNone after `timeout_ms`.
  virtual int ReadKey(int timeout_ms) = 0;
  virtual int Width() const = 0;
  virtual int Height() const = 0;
  virtual void Draw(const ScreenModel& screen) = 0;
};

inline constexpr double kPollSeconds = 0.05;
inline constexpr int kKeyTimeoutMs = 20;

// True when `next` must be drawn: nothing drawn yet, or a different picture (or size).
bool NeedsRedraw(const std::optional<ScreenModel>& drawn, const ScreenModel& next);

// Runs the wizard to its end on `terminal`. Returns 0 when done or saved and left, 1 when the
// last screen was an error shown to the operator.
int RunTuiLoop(WizardDriver& driver, TuiTerminal& terminal);

}  // namespace accelcal::ui
