// Small text helpers for the TUI's renderer: ASCII folding, wrapping, numbers with NaN as "--".
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace accelcal::ui {

// The engine's text may hold UTF-8 (a dash, a degree sign); the TUI draws ASCII only, so the
// few characters it uses are folded and any other non-ASCII character becomes '?'.
std::string Asciify(std::string_view text);

// Breaks `text` into lines of at most `width` characters at blanks (a word longer than the
// width is cut). An empty text gives no lines.
std::vector<std::string> Wrap(std::string_view text, int width);

// `value` with `decimals` decimals, right-aligned in `width`; NaN is drawn as "--".
std::string FormatNumber(double value, int decimals, int width);

// `text` cut to `width` characters.
std::string Clip(std::string_view text, int width);

}  // namespace accelcal::ui
