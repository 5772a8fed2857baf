// The noise analysis of one record (noise_analysis.h), read in passes from its source so that
// its length costs no memory: the first pass checks t and the readings and sums the means, the
// second sums the means the normality test takes (in units of the largest magnitude), further
// passes only when the median interval is not yet known (replay_selection.h), and the last
// computes the deviations' moments and feeds the Welch average. The figures are those of the
// same arithmetic over whole vectors, to the last bit (the sums run in the same order).
#pragma once

#include "accelcal/analysis/noise_analysis.h"
#include "accelcal/calibration/apply.h"

namespace accelcal::analysis {

// `applier`, when not null, converts each reading (the report's unit is then m/s^2). Throws
// accelcal::Error as AnalyzeNoise does.
RecordNoise AnalyzeRecordNoise(const NoiseRecordSource& source, const NoiseAnalysisOptions& options,
                               const CalibrationApplier* applier);

}  // namespace accelcal::analysis
