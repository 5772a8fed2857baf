// ui::RunTui: the ncurses wizard (ui/frontend.h). The loop is in tui_loop.cpp, the drawing in
// render.cpp, the keys in keys.cpp, curses in term.cpp.
#include "frontend.h"
#include "tui/term.h"
#include "tui/tui_loop.h"

namespace accelcal::ui {

int RunTui(WizardDriver& driver) {
  try {
    CursesTerminal terminal(ColorRequested());
    return RunTuiLoop(driver, terminal);
  } catch (...) {
    // Catching guarantees the unwinding that ends curses before the error is printed.
    throw;
  }
}

}  // namespace accelcal::ui
