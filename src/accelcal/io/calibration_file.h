// The calibration file: JSON, format "accelcal-calibration/1" (schema in docs/formats.md), the file
// form of the typed Calibration (calibration/calibration.h).
//
// Written with full round-trip precision; read strictly: a missing field, a wrong type, a
// non-finite number or an unknown format is an InputError naming the file and the field, so a
// damaged file is never applied as if it were good. Optional fields (added by later versions:
// the stages, the diagnosis) may be absent, never of the wrong type. A wizard session's result
// (the same JSON with its gaps beside) is session_result_file.h's.
#pragma once

#include <string>

#include "accelcal/calibration/calibration.h"

namespace accelcal {

inline constexpr const char* kCalibrationFormat = "accelcal-calibration/1";

// The calibration as JSON text (2-space indent).
std::string CalibrationToJsonText(const Calibration& cal);
// `text` read strictly; `source_name` names it in errors.
Calibration CalibrationFromJsonText(const std::string& text, const std::string& source_name);

void WriteCalibrationFile(const std::string& path, const Calibration& cal);
// Reads `path` once (a pipe works).
Calibration ReadCalibrationFile(const std::string& path);

}  // namespace accelcal
