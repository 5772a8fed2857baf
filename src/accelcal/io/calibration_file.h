// The calibration file: JSON, format "accelcal-calibration/1" (schema in README.md), the file
// form of the typed Calibration (calibration/calibration.h).
//
// Written with full round-trip precision; read strictly: a missing field, a wrong type, a
// non-finite number or an unknown format is an InputError naming the file and the field, so a
// damaged file is never applied as if it were good. Optional fields (added by later versions:
// the stages, the diagnosis) may be absent, never of the wrong type.
#pragma once

#include <string>

#include "accelcal/calibration/calibration.h"
#include "accelcal/report/report_model.h"

namespace accelcal {

inline constexpr const char* kCalibrationFormat = "accelcal-calibration/1";

// The calibration as JSON text (2-space indent).
std::string CalibrationToJsonText(const Calibration& cal);
// `text` read strictly; `source_name` names it in errors.
Calibration CalibrationFromJsonText(const std::string& text, const std::string& source_name);

// A wizard session's result: the calibration file's JSON with, beside it, the session's gaps
// (key "session_gaps": the steps skipped or missing and the identification missing), so that a
// report made later gives the verdict the wizard gave. `accelcal apply` reads it as it reads a
// calibration file.
std::string SessionResultJsonText(const Calibration& cal, const SessionGaps& gaps);

// The analyses a calibration file or a session's result may carry beside the calibration (keys
// "allan" and "noise", README "Reports") and a session's gaps ("session_gaps"), into `inputs`
// (strictly read; absent keys leave `inputs` as it is).
void ReadAnalysesFromResultText(const std::string& text, const std::string& source_name,
                                ReportInputs* inputs);

void WriteCalibrationFile(const std::string& path, const Calibration& cal);
// Reads `path` once (a pipe works).
Calibration ReadCalibrationFile(const std::string& path);

}  // namespace accelcal
