// A wizard session's result: the calibration file's JSON (calibration_file.h) with, beside it,
// the session's gaps (key "session_gaps": the steps skipped or missing and the identification
// missing), so that a report made later gives the verdict the wizard gave. `accelcal apply`
// reads it as it reads a calibration file. And what a calibration file or a session's result
// may carry beside the calibration for a report (the "allan", "noise" and "session_gaps" keys,
// docs/certificate.md, "Reports").
#pragma once

#include <string>

#include "accelcal/calibration/calibration.h"
#include "accelcal/report/report_model.h"
#include "accelcal/session/session_gaps.h"

namespace accelcal {

// The session's result as JSON text (2-space indent).
std::string SessionResultJsonText(const Calibration& cal, const SessionGaps& gaps);

// The analyses and gaps of a calibration file's or a session result's `text`, into `inputs`
// (strictly read: an InputError naming `source_name` and the field; absent keys leave `inputs`
// as it is).
void ReadAnalysesFromResultText(const std::string& text, const std::string& source_name,
                                ReportInputs* inputs);

}  // namespace accelcal
