// The record analysis (analysis/record_analysis.h) as text for a terminal or paper (80 columns):
// the record, then per axis the IEEE 952 read-offs and the drift, then the notes. The same
// figures as the Allan file (io/allan_file.h).
#pragma once

#include <string>

#include "accelcal/analysis/record_analysis.h"

namespace accelcal {

// `source` names what was analysed. Missing figures print as "-".
std::string FormatAllanText(const RecordAnalysis& analysis, const std::string& source);

}  // namespace accelcal
