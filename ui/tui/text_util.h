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

// The engine's text lines fitted to `width` columns: a longer line is wrapped at blanks, its
// leading blanks kept and its continuation lines indented two more, so nothing is cut at the
// right edge (the diagnosis's tables, long sentences). `width` <= 0: the lines as they are.
std::vector<std::string> WrapLines(const std::vector<std::string>& lines, int width);

// `value` with `decimals` decimals, right-aligned in `width`; NaN is drawn as "--".
std::string FormatNumber(double value, int decimals, int width);

// `text` cut to `width` characters.
std::string Clip(std::string_view text, int width);

}  // namespace accelcal::ui
