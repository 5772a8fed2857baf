// The lab's register (report/lab_register.h) as JSON, for `accelcal lab history|due|equipment
// --format json` (2-space indent, a final newline; absent values are null):
//   history:   {"device", "device_type", "calibrations": [{"certificate_number", "session",
//               "session_uuid", "bench", "date_utc", "verdict", "status", "procedure",
//               "operator", "approved_by", "approved_utc", "withdrawn_by", "withdrawn_utc",
//               "withdrawn_reason"}]}
//   due:       {"today", "within_days", "due": [{"kind": "device"|"equipment", "id", "type",
//               "name", "last", "last_date", "due_date", "days_left"}]}
//   equipment: {"equipment": [{"id", "kind", "name", "certificate_ref", "calibrated_on",
//               "valid_until", "days_left", "registered", "valid"}]}
#pragma once

#include <string>
#include <vector>

#include "accelcal/report/lab_register.h"

namespace accelcal {

std::string LabHistoryJsonText(const LabHistory& history);
std::string LabDueJsonText(const LabDueList& due);
std::string LabEquipmentJsonText(const std::vector<LabEquipmentStatus>& equipment);

}  // namespace accelcal
