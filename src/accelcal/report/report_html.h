// The calibration report as one self-contained HTML file: embedded CSS (with an @media print
// stylesheet for A4 paper), tables, and inline SVG plots (svg_plot.h): the residual of every
// capture before and after each adopted effect, the captures' magnitudes against their
// reference, and the Allan deviation with its confidence band and read-offs when present.
//
// No external reference of any kind (no URL, no script, no font or image to fetch). Every
// user-typed string (device, operator, place, labels, notes, file names) is escaped.
#pragma once

#include <string>

#include "accelcal/report/report_model.h"

namespace accelcal {

std::string RenderReportHtml(const ReportModel& model);

}  // namespace accelcal
