// Text plots of a running record (ui/tui): the drift of each axis against time and the Allan
// deviation on log-log axes. ASCII only, like the rest of the screen model (a cell is one
// char, so braille or block glyphs, which are several bytes of UTF-8, would break the grid):
// each row has three sub-levels, '.' low, '-' middle and '\'' high, which triples the
// vertical resolution. Meaning never depends on colour (NO_COLOR draws the same text).
#pragma once

#include <string>
#include <vector>

#include "accelcal/app/wizard/wizard_view.h"

namespace accelcal::ui {

// The drift of `axis` (0 x, 1 y, 2 z) in `rows` rows of `width` characters: time runs from 0
// (left) to the record's duration (right), so the trace grows as the record goes; the value
// range is the axis' own (min..max of its points, widened to 1 count at least). Each row
// starts with a scale label ("+1.2", "-0.4") in the first kPlotLabelWidth columns. Empty
// rows when there is no point yet.
std::vector<std::string> DriftPlot(const RecordView& record, int axis, int width, int rows);

// The Allan curves of the three axes on log-log axes, markers 'x', 'y', 'z' ('*' where two
// meet), in `rows` rows of `width`; the first row names the ranges. One row
// "Allan curve: waiting for data" when every curve is empty.
std::vector<std::string> AllanPlot(const RecordView& record, int width, int rows);

inline constexpr int kPlotLabelWidth = 8;

}  // namespace accelcal::ui
