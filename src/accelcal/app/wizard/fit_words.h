// The fit in plain words for the technician's screen (issue 27, item 9): how many captures it
// used and how well they agree with one calibration, said against the sensor's own noise; the
// captures it left out with why; the capture that fits worst when it stands out. The statistics
// (the parameters' 1-sigma, chi2/dof, the condition number, the optimizer's result, every
// capture's residual) stay one key away, on d (report/fit_text.h's FormatFitReport).
#pragma once

#include <string>
#include <vector>

#include "accelcal/calibration/calibration.h"

namespace accelcal {

// Lines of at most 78 columns.
std::vector<std::string> FitInPlainWords(const Calibration& cal);

}  // namespace accelcal
