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
// For pipes, scripts and terminals without curses (ui/line_mode.cpp). While a question waits the
// source is read (and what the question does not use dropped), as the full screen does.
int RunLineMode(WizardDriver& driver, std::istream& in, std::ostream& out);
// The same with the answers read from the file descriptor `fd` (stdin, the terminal), waited
// for with a timeout so that the source is read while a question waits. `terminal`: while the
// wizard is busy (settling, capturing) a line typed there is read at once (`q` quits; anything
// else is ignored); not a terminal (a pipe, a script): lines are read only when a question is
// asked, so scripted answers keep their order.
int RunLineModeOn(WizardDriver& driver, int fd, bool terminal, std::ostream& out);

}  // namespace accelcal::ui
