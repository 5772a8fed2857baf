// The capture flow's blocks (issue 15): the confirmation of an accepted capture, the time line
// (this capture, its give-up, the session's estimate), the figures behind a message (one key
// away: `d`), and the final verdict. Stacked by ui/tui/render.cpp with the other blocks.
#pragma once

#include <string>
#include <vector>

#include "accelcal/app/wizard/wizard_view.h"
#include "tui/render.h"
#include "tui/screen_model.h"

namespace accelcal::ui {

// "[DONE] +z up done: 10.0 s, |a| ~10.12 m/s^2 by the datasheet, noise 1.6 counts"; empty without one.
std::vector<Line> NoticeBlock(const WizardView& view, int width);
// "[LINK] The device restarted ...": what the source noticed, in words; with `state.details`,
// its figures under it. Empty without one.
std::vector<Line> SourceNoticeBlock(const WizardView& view, const RenderState& state, int width);
// "time     4 s left of this capture; gives up in 52 s; session: about 14 min left (estimate)",
// wrapped; empty without a time.
std::vector<Line> TimeBlock(const WizardView& view, int width);
// With `state.details`: the figures behind the message, wrapped; without: nothing (the keys
// line offers `d`).
std::vector<Line> DetailBlock(const WizardView& view, const RenderState& state, int width);
// The final screen's verdict, marked and coloured by its outcome: "[PASS] Verdict: PASS".
std::vector<Line> VerdictBlock(const WizardView& view, int width);
// The view's text lines as the TUI shows them, fitted to `width`: on the final screen without
// the summary's "Verdict: ..." line, which VerdictBlock already draws above them (line mode and
// the exit summary print it, having no verdict block). Scrolling counts these lines.
std::vector<std::string> ScreenTextLines(const WizardView& view, int width);

}  // namespace accelcal::ui
