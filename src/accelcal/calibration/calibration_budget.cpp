#include "accelcal/calibration/calibration_budget.h"

#include <memory>

#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/calibration/diagnosis/extended_model.h"

namespace accelcal {

UncertaintyBudget MakeCalibrationBudget(const DiagnosisReport& diagnosis, bool adopt_effects,
                                        const std::vector<Capture>& all, double gravity_mps2,
                                        const ReferenceUncertainties& references) {
  const bool extended = adopt_effects && !diagnosis.adopted.empty();
  const FitSummary& fit = extended ? diagnosis.final_fit : diagnosis.base;
  if (!fit.IsUsable()) return {};
  std::unique_ptr<ResidualModel> model;
  if (extended) {
    std::vector<const Effect*> effects;
    for (const AdoptedEffect& a : diagnosis.adopted)
      if (const Effect* e = FindEffect(a.name)) effects.push_back(e);
    model = std::make_unique<ExtendedResidualModel>(effects, diagnosis.context);
  } else {
    model = std::make_unique<BaseResidualModel>();
  }
  // The captures the fit used, in its order (its residuals list them).
  std::vector<FitCapture> used;
  for (const CaptureResidual& r : fit.residuals)
    for (const Capture& c : all)
      if (c.id == r.id) used.push_back(MakeFitCapture(c));
  if (used.size() != fit.residuals.size()) return {};
  return MakeUncertaintyBudget(*model, used, fit, gravity_mps2, references);
}

}  // namespace accelcal
