// What the TUI leaves on the terminal after it leaves the alternate screen: the final view's
// words (the verdict and the headline numbers at the end, "Saved ... run the wizard on it again
// to resume" after q, the problem after a failure), as line mode prints them, so that the
// outcome is not lost with the full screen.
#pragma once

#include <iosfwd>

#include "accelcal/app/wizard/wizard_view.h"

namespace accelcal::ui {

void PrintExitSummary(const WizardView& view, std::ostream& out);

}  // namespace accelcal::ui
