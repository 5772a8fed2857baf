#include "accelcal/app/disagreeing_captures.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "accelcal/base/chi_square.h"
#include "accelcal/calibration/diagnosis/extended_model.h"
#include "accelcal/calibration/diagnosis/leave_one_out.h"

namespace accelcal {
namespace {

std::vector<FitCapture> UsedFitCaptures(const std::vector<Capture>& captures) {
  std::vector<FitCapture> used;
  for (const Capture& c : captures)
    if (c.used()) used.push_back(MakeFitCapture(c));
  return used;
}

bool Explained(const DiagnosisReport& d) {
  return d.consistent || (!d.adopted.empty() && !d.unexplained);
}

// True when every effect `without` adopts was adopted in `with` too. Leaving a capture out and
// adopting an effect on the rest are two hypotheses chosen on the same captures: the capture is
// the one the current model predicts worst, and an effect then found on the rest was tested
// without the capture that contradicts it (an effect the library lacks shows in a few poses;
// take the one that shows it most out and a library effect can bend to the rest: an asymmetric
// scale on x leaves -x up the worst predicted, and the others then take a quadratic term). A
// capture is left out only as a bad capture: the rest must be explained by the model it was
// judged against, with no new effect.
bool NoNewEffect(const DiagnosisReport& without, const DiagnosisReport& with) {
  // Only what the model judged holds: an effect adopted on the whole set and then withdrawn (its
  // residuals not what noise explains) was found wanting with the capture in, and taking the
  // capture out is exactly what would let it pass (measured: an asymmetric x scale withdraws a
  // quadratic term, then the worst run is left out and the quadratic kept).
  const std::vector<std::string> had = with.adopted_names();
  for (const std::string& name : without.adopted_names())
    if (std::find(had.begin(), had.end(), name) == had.end()) return false;
  return true;
}

// The left-out predictions of the diagnosis's final model.
LeaveOneOutResult PredictFinal(const DiagnosisReport& d, const std::vector<FitCapture>& used,
                               const FitOptions& fit) {
  std::vector<const Effect*> effects;
  for (const AdoptedEffect& a : d.adopted)
    if (const Effect* e = FindEffect(a.name)) effects.push_back(e);
  const ExtendedResidualModel model(effects, d.context);
  LeastSquaresOptions solver = fit.solver;
  solver.gravity_mps2 = fit.gravity.gravity_mps2;
  return PredictLeftOut(model, used, d.final_fit.parameters, solver);
}

std::string WhatToCheck(const Capture& c) {
  if (c.kind == CaptureKind::kTurntable)
    return fmt::format("check the run's stated radius ({:g} m) and speed ({:g} rpm)", c.radius_m, c.rpm);
  return "check the pose (the right face, held still)";
}

std::string Reason(const Capture& c, const LeaveOneOutPrediction& p, size_t others) {
  return fmt::format("disagrees with the other captures: the {} others predict its magnitude "
                     "{:.4g} m/s^2 off ({:.0f} times its noise) and agree without it; {}",
                     others, p.residual_mps2, std::fabs(p.z), WhatToCheck(c));
}

void Warn(DiagnosisReport* d, const std::string& warning) {
  d->base.warnings.push_back(warning);
  if (d->final_fit.IsUsable()) d->final_fit.warnings.push_back(warning);
  for (FitSummary& s : d->stages) s.warnings.push_back(warning);
}

Capture* CaptureWithId(std::vector<Capture>& captures, int id) {
  for (Capture& c : captures)
    if (c.id == id && c.used()) return &c;
  return nullptr;
}

// Refuses the fit: the captures disagree and no capture alone explains it.
void Refuse(const LeaveOneOutResult& loo, DiagnosisReport* d) {
  std::vector<size_t> order(loo.predictions.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return std::fabs(loo.predictions[a].z) > std::fabs(loo.predictions[b].z);
  });
  std::vector<std::string> worst;
  for (size_t k = 0; k < std::min<size_t>(3, order.size()); ++k) {
    const LeaveOneOutPrediction& p = loo.predictions[order[k]];
    worst.push_back(fmt::format("{} ({:.4g} m/s^2 off, {:.0f} sigma)", p.id, p.residual_mps2, std::fabs(p.z)));
  }
  const FitSummary& f = d->final_fit;
  const std::string why =
      d->ambiguous.size() == 2
          ? fmt::format("{} and {} explain them alike but imply different calibrations",
                        d->ambiguous[0], d->ambiguous[1])
          : std::string("no effect of the library explains them and no capture alone does");
  d->base.termination = FitTermination::kInvalidInput;
  const std::string next = d->next_captures.empty() ? std::string() : "; next: " + d->next_captures;
  // Two effects that explain the residuals alike are the cause, not captures that disagree.
  if (d->ambiguous.size() == 2)
    d->base.message = fmt::format(
        "chi2/dof {:.4g} (residual RMS {:.4g} m/s^2, {:.0f} times what the captures' noise "
        "explains) is not a calibration: {}, and these captures cannot tell them apart{}",
        f.Chi2PerDof(), f.residual_rms_mps2, std::sqrt(f.Chi2PerDof()), why, next);
  else
    d->base.message = fmt::format(
        "the captures disagree with each other: chi2/dof {:.4g} (residual RMS {:.4g} m/s^2, {:.0f} "
        "times what their noise explains) is not a calibration; {}; predicted worst from the "
        "others: {} (check their stated radius and speed, or their pose){}",
        f.Chi2PerDof(), f.residual_rms_mps2, std::sqrt(f.Chi2PerDof()), why, fmt::join(worst, ", "), next);
  d->final_fit = d->base;
  d->adopted.clear();
  d->stages.clear();
  d->conclusion = "no diagnosis: " + d->base.message;
}

}  // namespace

void ResolveDisagreeingCaptures(std::vector<Capture>& captures, const FitOptions& fit,
                                const DiagnosisOptions& diagnosis_options,
                                const DisagreementOptions& options, DiagnosisReport* d) {
  if (!d->base.IsUsable()) return;
  std::vector<FitCapture> used = UsedFitCaptures(captures);
  const int limit = std::min(options.max_left_out, std::max(1, static_cast<int>(used.size()) / 9));
  for (int left = 0; left < limit && !Explained(*d); ++left) {
    const LeaveOneOutResult loo = PredictFinal(*d, used, fit);
    if (loo.worst_index < 0 || !(loo.worst_abs_z >= options.min_abs_z)) break;
    const LeaveOneOutPrediction& worst = loo.predictions[static_cast<size_t>(loo.worst_index)];
    std::vector<FitCapture> rest = used;
    rest.erase(rest.begin() + loo.worst_index);
    DiagnosisReport without = Diagnose(rest, fit, diagnosis_options);
    if (!without.base.IsUsable() || !Explained(without) || !NoNewEffect(without, *d)) break;
    Capture* c = CaptureWithId(captures, worst.id);
    if (c == nullptr) break;
    c->rejection_reason = Reason(*c, worst, rest.size());
    *d = std::move(without);
    Warn(d, fmt::format("capture {} was left out: it disagrees with the other captures (its "
                        "reason says by how much)", worst.id));
    used = std::move(rest);
  }
  if (!d->final_fit.IsUsable() || d->final_fit.dof <= 0 ||
      !(d->final_fit.Chi2PerDof() > options.refuse_chi2_per_dof))
    return;
  if (options.refuse)
    Refuse(PredictFinal(*d, used, fit), d);
  else
    Warn(d, fmt::format("chi2/dof {:.4g}: the residuals are {:.0f} times what the captures' noise "
                        "explains; this is hardly a calibration (let the diagnosis look for the cause)",
                        d->final_fit.Chi2PerDof(), std::sqrt(d->final_fit.Chi2PerDof())));
}

}  // namespace accelcal
