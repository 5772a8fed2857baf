// A stored calibration as text (for `accelcal report`): parameters with their 1-sigma
// uncertainties, gravity, residuals, adopted effects and the capture table. Works from the
// calibration file alone (no FitSummary needed).
#pragma once

#include <string>

#include "accelcal/calibration/calibration.h"

namespace accelcal {

std::string FormatCalibrationText(const Calibration& cal);

}  // namespace accelcal
