// The calibration report as plain text for terminals and paper: at most 80 columns per line,
// ASCII only in what the program writes (user-typed text is kept, control characters become
// '?'), sections with numbered headings, and signature lines at the end.
#pragma once

#include <string>

#include "accelcal/report/report_model.h"

namespace accelcal {

std::string RenderReportText(const ReportModel& model);

}  // namespace accelcal
