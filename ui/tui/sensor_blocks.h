// A fixture's sensors on the capture screens (issue 31): each sensor's stillness and orientation
// (WizardView::sensors, app/fixture/sensor_look.h) compactly, 32 sensors on a 100x30 terminal.
#pragma once

#include <vector>

#include "accelcal/app/wizard/wizard_view.h"
#include "tui/render.h"
#include "tui/screen_model.h"

namespace accelcal::ui {

// Without `state.details`: a head line ("sensors  7 of 8 still and in their pose") and a grid of
// cells, "B03 ok" or "B02 ! moving", as many to a row as `width` takes. With it: one line per
// sensor with its figures, those not ok first. Empty for one sensor.
std::vector<Line> SensorsBlock(const WizardView& view, const RenderState& state, int width);

}  // namespace accelcal::ui
