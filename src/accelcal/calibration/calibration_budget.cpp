#include "accelcal/calibration/calibration_budget.h"

#include <memory>

#include "accelcal/calibration/excess_scatter.h"

namespace accelcal {

UncertaintyBudget MakeCalibrationBudget(const DiagnosisReport& diagnosis, bool adopt_effects,
                                        const std::vector<Capture>& all, double gravity_mps2,
                                        const ReferenceUncertainties& references) {
  const bool extended = adopt_effects && !diagnosis.adopted.empty();
  const FitSummary& fit = extended ? diagnosis.final_fit : diagnosis.base;
  if (!fit.IsUsable()) return {};
  const std::unique_ptr<ResidualModel> model = ModelOfDiagnosis(diagnosis, extended);
  const std::vector<FitCapture> used = CapturesOfFit(fit, all);
  if (used.empty()) return {};
  return MakeUncertaintyBudget(*model, used, fit, gravity_mps2, references);
}

}  // namespace accelcal
