// Placeholder so this branch links: replaced by ui/tui/tui_app.cpp (the ncurses TUI, written on
// another branch); delete this file at the merge. Falls back to the plain line mode.
#include <iostream>

#include "frontend.h"

namespace accelcal::ui {

int RunTui(WizardDriver& driver) { return RunLineMode(driver, std::cin, std::cout); }

}  // namespace accelcal::ui
