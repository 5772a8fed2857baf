// The uncertainty budget (uncertainty_budget.h) of the calibration a diagnosis ends with: the
// model it chose (the final one with its adopted effects, or the base one), over the captures
// that fit used, with the sensitivities of that model.
#pragma once

#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/calibration/diagnosis/diagnosis.h"
#include "accelcal/calibration/uncertainty_budget.h"

namespace accelcal {

// `all` holds at least every capture the chosen fit used (matched by id); the chosen fit must
// be usable (else the budget is empty).
UncertaintyBudget MakeCalibrationBudget(const DiagnosisReport& diagnosis, bool adopt_effects,
                                        const std::vector<Capture>& all, double gravity_mps2,
                                        const ReferenceUncertainties& references);

}  // namespace accelcal
