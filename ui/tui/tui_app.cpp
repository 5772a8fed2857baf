// ui::RunTui: the ncurses wizard (ui/frontend.h). The loop is in tui_loop.cpp, the drawing in
// render.cpp, the keys in keys.cpp, curses in term.cpp.
#include <iostream>

#include "frontend.h"
#include "tui/exit_summary.h"
#include "tui/term.h"
#include "tui/tui_loop.h"

namespace accelcal::ui {

int RunTui(WizardDriver& driver) {
  int status = 0;
  {
    // Leaving this scope (also by an exception) ends curses before anything is printed.
    CursesTerminal terminal(ColorRequested());
    status = RunTuiLoop(driver, terminal);
  }
  // The alternate screen is gone: the outcome stays on the terminal.
  PrintExitSummary(driver.View(), std::cout);
  return status;
}

}  // namespace accelcal::ui
