// The blocks the renderer stacks (ui/tui/render.cpp), each built from the view at a width.
#pragma once

#include <vector>

#include "accelcal/app/wizard/wizard_view.h"
#include "tui/render.h"
#include "tui/screen_model.h"

namespace accelcal::ui {

Line HeaderLine(const WizardView& view, int width);
std::vector<Line> TitleBlock(const WizardView& view, int width);
std::vector<Line> PromptBlock(const WizardView& view, int width);
// The live reading, tilt, stability and progress rows (without the drawing).
std::vector<Line> ReadingBlock(const WizardView& view);
// The reading rows beside the pose drawing; empty when there is no drawing.
std::vector<Line> PanelWithDrawing(const WizardView& view);
// A running record in `rows` rows: elapsed of duration with a gauge, what is recorded (chunks,
// samples, gaps), movements, the live reading, the drift plot per axis (as tall as the rows
// allow, up to 6 rows an axis; left out below 3) and the Allan curve panel.
std::vector<Line> RecordBlock(const WizardView& view, int width, int rows);
std::vector<Line> ProblemBlock(const WizardView& view, int width);
std::vector<Line> InputBlock(const WizardView& view, const RenderState& state, int width);
std::vector<Line> StatusBlock(const WizardView& view);
// The keys that work now, named as the TUI sends them (tui/keys.h KeyName: in a text field the
// navigation has keys that cannot be typed; Esc clears first when text is `typed`), after the
// two that always work (quit and help). Within `width` columns (0: no limit) whole entries only.
Line KeysLine(const WizardView& view, bool scrollable, bool typed = false, int width = 0);

}  // namespace accelcal::ui
