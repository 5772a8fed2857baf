// The TUI's drawing as a pure function: a WizardView and a terminal size in, a ScreenModel out.
// No curses here, so view tests render into fixed sizes and compare with golden text.
//
// Layout, top to bottom: header (step k of n, session, procedure, resumed), step title, prompt,
// the pose panel (prism drawing beside the live reading, stability gauge and capture progress),
// problem and hint, the input line, the scrollable text lines (fit, diagnosis, report), the
// source status and the key hints on the last row. When the terminal is too small the drawing
// goes first, then the status, the panel, the prompt, ...; the header and the keys stay.
#pragma once

#include <string>

#include "accelcal/app/wizard/wizard_view.h"
#include "tui/screen_model.h"

namespace accelcal::ui {

// What the front end adds to the engine's view: the text being typed and the scroll position
// of the text lines (first line shown; clamped by the renderer).
struct RenderState {
  std::string edit_text;
  int scroll = 0;
  bool help = false;  // the help overlay (tui/help_overlay.h) in place of the step's blocks
  bool details = false;  // `d`: the figures behind the capture's message are shown
};

ScreenModel Render(const WizardView& view, const RenderState& state, int width, int height);

}  // namespace accelcal::ui
