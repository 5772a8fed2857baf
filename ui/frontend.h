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
// For pipes, scripts and terminals without curses (ui/line_mode.cpp).
int RunLineMode(WizardDriver& driver, std::istream& in, std::ostream& out);

}  // namespace accelcal::ui
