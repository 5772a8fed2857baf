// The wizard's front ends. Each runs one loop: poll the driver, draw its view, map input to
// intents, until the view says finished or the operator quits. Both return the process exit
// status (0 done or saved and left; 1 a failure shown to the operator).
#pragma once

#include <iosfwd>

#include "accelcal/app/wizard/wizard_driver.h"

namespace accelcal::ui {

// Full-screen ncurses wizard (ui/tui/). Needs a terminal on stdin and stdout.
int RunTui(WizardDriver& driver);

// Plain prompts on `out`, one answer per line from `in`; an empty answer takes the default.
// For pipes, scripts and terminals without curses (ui/line_mode.cpp). `interrupt_fd`: the
// file descriptor `in` reads, when it is a terminal: while the wizard is busy (settling,
// capturing) a line typed there is read at once (`q` quits; anything else is ignored). -1 (a
// pipe, a script): lines are read only when a question is asked, so scripted answers keep
// their order.
int RunLineMode(WizardDriver& driver, std::istream& in, std::ostream& out, int interrupt_fd = -1);

}  // namespace accelcal::ui
