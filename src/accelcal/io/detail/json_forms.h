// The JSON values behind io's file formats, for io's own files and for tests that look inside
// them. Nothing outside io includes this: the rest of the program reads and writes typed values
// and text (allan_file.h, noise_file.h, report_json.h, calibration_file.h).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "accelcal/analysis/noise_analysis.h"
#include "accelcal/analysis/record_analysis.h"
#include "accelcal/io/export/kalibr_imu_yaml.h"
#include "accelcal/report/device_history.h"
#include "accelcal/report/report_model.h"

namespace accelcal {

// calibration_file.h's format.
nlohmann::json CalibrationToJson(const Calibration& cal);
Calibration CalibrationFromJson(const nlohmann::json& j, const std::string& source_name);
// allan_file.h's format.
nlohmann::json RecordAnalysisToJson(const RecordAnalysis& analysis, const std::string& source,
                                    double drift_window_s);
// Strict readers of the report's analysis sections: a wrong type, a non-finite number, an
// unknown unit or arrays of different lengths throw InputError naming `source` and the field.
// At least one axis must be present. Null figures (and null adev points, as `accelcal allan`
// writes them) read as NaN: absent. ParseNoiseJson also reads `accelcal noise`'s file
// ("accelcal-noise/1": records[0]'s std and density, bias repeatability =
// repeatability.std_of_means).
AllanSection ParseAllanJson(const nlohmann::json& j, const std::string& source);
NoiseSection ParseNoiseJson(const nlohmann::json& j, const std::string& source);
nlohmann::json AllanToJson(const AllanSection& a);
nlohmann::json NoiseToJson(const NoiseSection& n);
// noise_file.h's format.
nlohmann::json NoiseReportToJson(const analysis::NoiseReport& report);
// report_json.h's format.
nlohmann::json ReportToJson(const ReportModel& model);
// The Kalibr figures of an Allan file (kalibr_imu_yaml.h, AllanNoiseForKalibrText).
AllanNoiseFigures AllanNoiseForKalibr(const nlohmann::json& allan, const Calibration& cal,
                                      const std::string& source_name);
// history_json.h's format.
nlohmann::json DeviceHistoryToJson(const DeviceHistory& history);
// A session's gaps (the result's key "session_gaps"; the report's too), and strictly back.
nlohmann::json SessionGapsToJson(const SessionGaps& gaps);
SessionGaps SessionGapsFromJson(const nlohmann::json& j, const std::string& source);
// The "allan", "noise" and "session_gaps" keys of a session's result or a calibration file,
// when present (strictly read).
void ReadAnalysesFromResult(const nlohmann::json& result, const std::string& source,
                            ReportInputs* inputs);

}  // namespace accelcal
