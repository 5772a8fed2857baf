// All curses handling of the TUI in one place (docs/STYLE.md: htop's CRT.c): setup and teardown,
// the role -> colour table with its monochrome fallback, key translation, and restoring the
// terminal on every exit: normal return and exceptions (the destructor), fatal and terminating
// signals (a handler ends curses, then re-raises the signal with its default action).
#pragma once

#include "tui/screen_model.h"
#include "tui/tui_loop.h"

namespace accelcal::ui {

// Colour unless NO_COLOR is set to a non-empty value (no-color.org) or the terminal has none.
bool ColorRequested();

class CursesTerminal final : public TuiTerminal {
 public:
  // Starts curses on the controlling terminal; `color` false forces monochrome.
  explicit CursesTerminal(bool color);
  ~CursesTerminal() override;
  CursesTerminal(const CursesTerminal&) = delete;
  CursesTerminal& operator=(const CursesTerminal&) = delete;

  int ReadKey(int timeout_ms) override;
  int Width() const override;
  int Height() const override;
  void Draw(const ScreenModel& screen) override;

 private:
  bool color_ = false;
  int drawn_width_ = -1;
  int drawn_height_ = -1;
};

}  // namespace accelcal::ui
