// Line mode's help, printed on "?" (or "help") alone on a line at any question, a text field
// included: what the step expects (app/wizard/step_help.h) and the answers that work now.
#pragma once

#include <iosfwd>
#include <string>

#include "accelcal/app/wizard/wizard_view.h"

namespace accelcal::ui {

// True for the lines that ask for the help.
bool IsHelpRequest(const std::string& trimmed_line);

void PrintLineModeHelp(const WizardView& view, std::ostream& out);

}  // namespace accelcal::ui
