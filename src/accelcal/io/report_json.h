// The calibration report as JSON, format "accelcal-report/1": the report model field by field
// (docs/certificate.md, "Reports"). NaN is written as null. It is a report, not a calibration: `accelcal
// apply` reads the calibration file (`accelcal export`, or `accelcal report --format
// calibration`).
#pragma once

#include <string>

#include "accelcal/report/report_model.h"

namespace accelcal {

inline constexpr const char* kReportFormat = "accelcal-report/1";

// The report as JSON text (2-space indent, a final newline).
std::string ReportJsonText(const ReportModel& model);

}  // namespace accelcal
