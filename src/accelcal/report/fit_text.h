// Plain-text renderings of a fit for terminals and logs (80 columns, no control codes).
#pragma once

#include <string>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/calibration/fit/fit_summary.h"
#include "accelcal/calibration/calibration.h"
#include "accelcal/acquire/static_detector.h"

namespace accelcal {

// "found 38 static intervals (threshold ... counts^2)" and one line per interval.
std::string FormatIntervals(const StaticDetection& detection, const StaticDetectorOptions& options);

// One line per capture: id, kind, samples, used or why not, residual when fitted.
std::string FormatCaptureTable(const std::vector<Capture>& captures, const FitSummary& summary);
std::string FormatCaptureTable(const std::vector<CalibrationCapture>& captures);

// The fit's FullReport (parameters with 1-sigma uncertainties, residual statistics,
// conditioning, warnings) followed by the capture table.
std::string FormatFitReport(const Calibration& cal, const FitSummary& summary);

// The nine results with their expanded uncertainty U (k = 2) as a certificate of `cal` states
// them (limit_checks.h: the budget's U, else twice the fit's 1-sigma, said so), each rounded to
// two significant digits of U, and what U does not hold.
std::string FormatExpandedResults(const Calibration& cal);

}  // namespace accelcal
