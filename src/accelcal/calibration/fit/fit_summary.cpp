#include "accelcal/calibration/fit/fit_summary.h"

#include <cmath>

#include <fmt/core.h>

namespace accelcal {

std::string_view FitTerminationToString(FitTermination t) {
  switch (t) {
    case FitTermination::kNotRun: return "not_run";
    case FitTermination::kConverged: return "converged";
    case FitTermination::kNoConvergence: return "no_convergence";
    case FitTermination::kNumericalFailure: return "numerical_failure";
    case FitTermination::kUnderdetermined: return "underdetermined";
    case FitTermination::kInvalidInput: return "invalid_input";
  }
  return "?";
}

std::string_view ScatterStructureToString(ScatterStructure s) {
  switch (s) {
    case ScatterStructure::kIndependent: return "independent";
    case ScatterStructure::kFlicker: return "flicker";
    case ScatterStructure::kRandomWalk: return "random_walk";
  }
  return "?";
}

bool ScatterStructureFromString(std::string_view text, ScatterStructure* out) {
  for (ScatterStructure s : {ScatterStructure::kIndependent, ScatterStructure::kFlicker,
                             ScatterStructure::kRandomWalk}) {
    if (text == ScatterStructureToString(s)) {
      *out = s;
      return true;
    }
  }
  return false;
}

std::string_view ScatterSizeUnit(ScatterStructure s) {
  return s == ScatterStructure::kRandomWalk ? "counts/sqrt(s)" : "counts";
}

bool FitSummary::IsHeld(int i) const { return FindHeld(i) != nullptr; }

const HeldParameter* FitSummary::FindHeld(int i) const {
  for (const HeldParameter& h : held)
    if (h.index == i) return &h;
  return nullptr;
}

SensorModel FitSummary::Model() const {
  if (parameters.size() < kNumBaseParameters) return SensorModel{};
  return SensorModel::FromVector(parameters.head(kNumBaseParameters));
}

std::string FitSummary::BriefReport() const {
  if (!IsUsable()) return fmt::format("fit {}: {}", FitTerminationToString(termination), message);
  // With as many fitted parameters as captures there are no degrees of freedom: the residuals
  // say nothing about the noise, and no ratio is printed (never the -1 that marks it inside).
  const std::string chi2_per_dof = dof > 0 ? fmt::format("{:.2f}", Chi2PerDof())
                                           : std::string("- (no degrees of freedom left)");
  return fmt::format("fit converged: {} captures, residual RMS {:.4f} m/s^2, chi2/dof {}, "
                     "condition {:.3g}{}{}",
                     num_captures, residual_rms_mps2, chi2_per_dof, condition_number,
                     held.empty() ? "" : fmt::format(", {} held", held.size()),
                     warnings.empty() ? "" : fmt::format(", {} warning(s)", warnings.size()));
}

std::string FitSummary::FullReport() const {
  std::string out = BriefReport() + "\n";
  if (!IsUsable()) return out;
  out += fmt::format("gravity used: {:.6f} m/s^2\n\nparameters (1-sigma):\n", gravity_mps2);
  for (int i = 0; i < parameters.size(); ++i) {
    const std::string unit = i < kNumBaseParameters ? std::string(ParameterUnit(i)) : "";
    if (IsHeld(i)) {
      out += fmt::format("  {:<12} {:>14.6f}    held        {}\n", parameter_labels[i], parameters(i), unit);
      continue;
    }
    out += fmt::format("  {:<12} {:>14.6f} +- {:<11.6f} {}\n", parameter_labels[i], parameters(i),
                       uncertainty(i), unit);
  }
  for (const HeldParameter& h : held)
    out += fmt::format("held: {} = {} (not fitted): {}\n", parameter_labels[h.index], h.value, h.reason);
  out += fmt::format("residuals: RMS {:.5f} m/s^2, max |r| {:.5f} m/s^2, chi2 {:.2f} on {} dof\n",
                     residual_rms_mps2, residual_max_abs_mps2, chi2, dof);
  if (uncertainty_scale > 1.0)
    out += fmt::format("uncertainties scaled by {:.2f} = sqrt(chi2/dof): the residuals exceed "
                       "what the captures' noise explains\n", uncertainty_scale);
  if (scatter)
    out += fmt::format("uncertainties from the scatter between the captures ({} structure, size "
                       "{:.3g} {}; up to {:.1f} times the noise-only 1-sigma, at least {:.1f} degrees "
                       "of freedom): the residuals exceed what the captures' noise explains\n",
                       ScatterStructureToString(scatter->structure), scatter->size,
                       ScatterSizeUnit(scatter->structure), scatter->ratio_to_noise, scatter->min_dof);
  if (most_correlated.first >= 0)
    out += fmt::format("most correlated: {} and {} (rho = {:+.3f})\n",
                       parameter_labels[most_correlated.first],
                       parameter_labels[most_correlated.second], most_correlated.rho);
  out += fmt::format("optimizer: NLopt {} after {} evaluations, Gauss-Newton polish {} iterations\n",
                     optimizer_result, optimizer_evaluations, gauss_newton_iterations);
  for (const std::string& w : warnings) out += "warning: " + w + "\n";
  return out;
}

}  // namespace accelcal
