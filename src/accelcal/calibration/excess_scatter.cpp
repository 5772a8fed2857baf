#include "accelcal/calibration/excess_scatter.h"

#include "accelcal/base/chi_square.h"
#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/calibration/diagnosis/extended_model.h"
#include "accelcal/calibration/fit/scatter_uncertainty.h"

namespace accelcal {
namespace {

void ApplyTo(const ResidualModel& model, const std::vector<Capture>& all, double consistency_p,
             FitSummary* fit) {
  if (!fit->IsUsable() || fit->dof <= 0 || fit->scatter) return;
  if (ChiSquareSurvival(fit->chi2, fit->dof) >= consistency_p) return;
  const std::vector<FitCapture> used = CapturesOfFit(*fit, all);
  if (used.empty()) return;
  const ScatterFit scatter = FitScatter(model, used, *fit);
  if (scatter.chosen >= 0) ApplyScatter(scatter, fit);
}

}  // namespace

std::unique_ptr<ResidualModel> ModelOfDiagnosis(const DiagnosisReport& diagnosis, bool extended) {
  if (!extended) return std::make_unique<BaseResidualModel>();
  std::vector<const Effect*> effects;
  for (const AdoptedEffect& a : diagnosis.adopted)
    if (const Effect* e = FindEffect(a.name)) effects.push_back(e);
  return std::make_unique<ExtendedResidualModel>(effects, diagnosis.context);
}

std::vector<FitCapture> CapturesOfFit(const FitSummary& fit, const std::vector<Capture>& all) {
  std::vector<FitCapture> used;
  for (const CaptureResidual& r : fit.residuals)
    for (const Capture& c : all)
      if (c.id == r.id) used.push_back(MakeFitCapture(c));
  if (used.size() != fit.residuals.size()) return {};
  return used;
}

void ApplyExcessScatter(const std::vector<Capture>& all, double consistency_p,
                        DiagnosisReport* diagnosis) {
  const bool extended = !diagnosis->adopted.empty();
  ApplyTo(*ModelOfDiagnosis(*diagnosis, false), all, consistency_p, &diagnosis->base);
  if (extended)
    ApplyTo(*ModelOfDiagnosis(*diagnosis, true), all, consistency_p, &diagnosis->final_fit);
  else
    diagnosis->final_fit = diagnosis->base;
}

}  // namespace accelcal
