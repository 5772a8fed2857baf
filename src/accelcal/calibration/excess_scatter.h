// The uncertainty of a calibration whose residuals exceed its captures' noise while no effect
// explains them (issue 29): the diagnosis's fits that fail the chi-square test take their
// uncertainty from the scatter between the captures (fit/scatter_uncertainty.h) instead of the
// sqrt(chi2/dof) scaling, which assumes that scatter independent from capture to capture.
#pragma once

#include <memory>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/calibration/diagnosis/diagnosis.h"
#include "accelcal/calibration/fit/fit_capture.h"
#include "accelcal/calibration/fit/residual_model.h"

namespace accelcal {

// The model of the diagnosis's final fit (with its adopted effects) when `extended`, else the
// base model.
std::unique_ptr<ResidualModel> ModelOfDiagnosis(const DiagnosisReport& diagnosis, bool extended);

// The captures `fit` used, in its order (its residuals list them), from `all` (matched by id);
// empty when one is missing.
std::vector<FitCapture> CapturesOfFit(const FitSummary& fit, const std::vector<Capture>& all);

// Replaces the uncertainty of the base and the final fit of `diagnosis` by the scatter's
// (scatter_uncertainty.h) where its residuals fail the chi-square test at `consistency_p`: the
// residuals exceed noise and the fit's model does not explain them. `all` holds the captures.
void ApplyExcessScatter(const std::vector<Capture>& all, double consistency_p,
                        DiagnosisReport* diagnosis);

}  // namespace accelcal
