// The help the TUI shows on ? or F1 in place of the step's panel: what the step expects, in plain
// words (app/wizard/step_help.h), and every key that works on this screen, named as the key bar
// names it (tui/keys.h). Any key closes it.
#pragma once

#include <vector>

#include "accelcal/app/wizard/wizard_view.h"
#include "tui/screen_model.h"

namespace accelcal::ui {

// The help's rows at `width` (wrapped; the renderer cuts what does not fit in its rows).
std::vector<Line> HelpBlock(const WizardView& view, int width);

}  // namespace accelcal::ui
