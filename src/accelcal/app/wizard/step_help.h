// What the current step expects, in plain words, for the help a front end shows on `?` (the TUI's
// overlay, line mode's help text). Built from the view alone, so every front end says the same;
// the keys are the front end's own (each names how its keys send the view's intents).
//
// Contract: never empty for a view that is not finished; each entry is one paragraph of plain
// text (the front end wraps it).
#pragma once

#include <string>
#include <vector>

#include "accelcal/app/wizard/wizard_view.h"

namespace accelcal {

std::vector<std::string> StepHelp(const WizardView& view);

}  // namespace accelcal
