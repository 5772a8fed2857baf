#include "accelcal/io/session_result_file.h"

#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/detail/json_values.h"

namespace accelcal {

std::string SessionResultJsonText(const Calibration& cal, const SessionGaps& gaps) {
  nlohmann::json j = CalibrationToJson(cal);
  j["session_gaps"] = SessionGapsToJson(gaps);
  return j.dump(2);
}

void ReadAnalysesFromResultText(const std::string& text, const std::string& source_name,
                                ReportInputs* inputs) {
  ReadAnalysesFromResult(detail::ParseJsonText(text, source_name), source_name, inputs);
}

}  // namespace accelcal
