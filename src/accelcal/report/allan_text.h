// The Allan analysis file (io/allan_file.h) as text for a terminal or paper (80 columns): the
// record, then per axis the IEEE 952 read-offs and the drift, then the notes.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace accelcal {

// `allan` as written by RecordAnalysisToJson. Missing figures print as "-".
std::string FormatAllanText(const nlohmann::json& allan);

}  // namespace accelcal
