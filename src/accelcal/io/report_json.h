// The calibration report as JSON, format "accelcal-report/1": the report model field by field
// (README "Reports"). NaN is written as null. It is a report, not a calibration: `accelcal
// apply` reads the calibration file (`accelcal export`, or `accelcal report --format
// calibration`).
#pragma once

#include <nlohmann/json.hpp>

#include "accelcal/report/report_model.h"

namespace accelcal {

inline constexpr const char* kReportFormat = "accelcal-report/1";

nlohmann::json ReportToJson(const ReportModel& model);

}  // namespace accelcal
