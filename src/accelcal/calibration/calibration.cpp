#include "accelcal/calibration/calibration.h"
#include "accelcal/calibration/pose_check.h"

#include <fmt/core.h>

#include "accelcal/calibration/diagnosis/diagnosis.h"
#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/calibration/fit/scatter_uncertainty.h"

namespace accelcal {
namespace {

// The residual of capture `id` in `summary`, or NaN when the summary did not use it.
const CaptureResidual* ResidualOf(const FitSummary& summary, int id) {
  if (!summary.IsUsable()) return nullptr;
  for (const CaptureResidual& r : summary.residuals)
    if (r.id == id) return &r;
  return nullptr;
}

CalibrationEffect MakeEffect(const AdoptedEffect& a) {
  CalibrationEffect e;
  e.name = a.name;
  for (size_t i = 0; i < a.parameters.size(); ++i)
    e.parameters.push_back({a.parameter_names[i], a.parameter_units[i], a.parameters[i], a.uncertainty[i]});
  e.rms_before_mps2 = a.before.rms_mps2;
  e.rms_after_mps2 = a.after.rms_mps2;
  e.chi2_per_dof_before = a.before.dof > 0 ? a.before.Chi2PerDof() : kNaN;
  e.chi2_per_dof_after = a.after.dof > 0 ? a.after.Chi2PerDof() : kNaN;
  const Effect* effect = FindEffect(a.name);
  e.corrects_readings = effect != nullptr && effect->CorrectsReadings();
  e.evidence = a.evidence;
  return e;
}

// The verdict's sentence for an uncertainty taken from the scatter between the captures.
std::string ScatterLimitWords(const ScatterModel& scatter) {
  return fmt::format("limited by the scatter between the captures: they disagree beyond their own "
                     "noise and no effect explains it, most likely {}; the uncertainties come from "
                     "that scatter (up to {:.1f} times what the noise alone gives)",
                     DescribeScatter(scatter), scatter.ratio_to_noise);
}

}  // namespace

const EffectParameter* CalibrationEffect::Find(std::string_view parameter) const {
  for (const EffectParameter& p : parameters)
    if (p.name == parameter) return &p;
  return nullptr;
}

const CalibrationEffect* Calibration::FindEffect(std::string_view name) const {
  for (const CalibrationEffect& e : effects)
    if (e.name == name) return &e;
  return nullptr;
}

std::vector<std::string> Calibration::EffectNames() const {
  std::vector<std::string> names;
  for (const CalibrationEffect& e : effects) names.push_back(e.name);
  return names;
}

FitStatistics MakeFitStatistics(const FitSummary& s) {
  FitStatistics f;
  f.termination = s.termination;
  f.captures_used = s.num_captures;
  f.dof = s.dof;
  f.chi2 = s.chi2;
  f.chi2_per_dof = s.dof > 0 ? s.Chi2PerDof() : kNaN;
  f.uncertainty_scale = s.uncertainty_scale;
  f.condition_number = s.condition_number;
  if (s.most_correlated.first >= 0) {
    f.most_correlated_first = s.parameter_labels[static_cast<size_t>(s.most_correlated.first)];
    f.most_correlated_second = s.parameter_labels[static_cast<size_t>(s.most_correlated.second)];
    f.most_correlated_rho = s.most_correlated.rho;
  }
  f.optimizer = fmt::format("NLopt SLSQP ({}, {} evaluations) + Gauss-Newton ({} iterations)",
                            s.optimizer_result, s.optimizer_evaluations, s.gauss_newton_iterations);
  f.warnings = s.warnings;
  f.scatter = s.scatter;
  return f;
}

std::vector<CalibrationCapture> MakeCalibrationCaptures(const std::vector<Capture>& all,
                                                        const FitSummary& summary) {
  std::vector<CalibrationCapture> out;
  for (const Capture& c : all) {
    const CaptureStats& stats = c.stats();
    CalibrationCapture r;
    r.id = c.id;
    r.kind = c.kind;
    r.label = c.label;
    r.used = c.used();
    r.reason = c.rejection_reason;
    r.n_samples = static_cast<long>(c.samples.size());
    r.radius_m = c.radius_m;
    r.rpm = c.rpm;
    r.t_start_s = c.samples.empty() ? kNaN : c.samples.front().t_s;
    r.t_end_s = c.samples.empty() ? kNaN : c.samples.back().t_s;
    r.mean_counts = stats.n > 0 ? stats.mean_counts : Eigen::Vector3d::Constant(kNaN);
    if (const CaptureResidual* res = r.used ? ResidualOf(summary, c.id) : nullptr) {
      r.residual_mps2 = res->residual_mps2;
      r.reference_mps2 = res->reference_mps2;
      r.sigma_mps2 = res->sigma_mps2;
    }
    out.push_back(std::move(r));
  }
  return out;
}

const HeldMark* Calibration::FindHeld(int index) const {
  if (index < 0 || index >= kNumBaseParameters) return nullptr;
  for (const HeldMark& h : held)
    if (h.name == ParameterName(index)) return &h;
  return nullptr;
}

Calibration MakeCalibration(const FitSummary& summary, const GravitySpec& gravity,
                            const std::vector<Capture>& all, const std::string& source) {
  Calibration cal;
  cal.model = summary.Model();
  cal.uncertainty = SensorModel::FromVector(summary.uncertainty.head(kNumBaseParameters));
  cal.gravity = gravity;
  cal.residual_rms_mps2 = summary.residual_rms_mps2;
  cal.residual_max_abs_mps2 = summary.residual_max_abs_mps2;
  cal.source = source;
  cal.fit = MakeFitStatistics(summary);
  // A capture set may state each pose asked for: a capture taken in another one is named.
  if (summary.IsUsable())
    for (std::string& w : CheckRequestedPoses(all, cal.model)) cal.fit.warnings.push_back(std::move(w));
  for (const HeldParameter& h : summary.held)
    if (h.index < kNumBaseParameters)
      cal.held.push_back({std::string(ParameterName(h.index)), h.value, h.reason});
  cal.captures = MakeCalibrationCaptures(all, summary);
  if (summary.scatter)
    cal.limited_by.push_back({"scatter", ScatterLimitWords(*summary.scatter)});
  cal.stages.push_back({"base model", summary.residual_rms_mps2});
  for (CalibrationCapture& c : cal.captures) c.stage_residuals_mps2 = {c.residual_mps2};
  return cal;
}

Calibration MakeCalibration(const DiagnosisReport& d, bool adopt_effects, const GravitySpec& gravity,
                            const std::vector<Capture>& all, const std::string& source) {
  const bool adopt = adopt_effects && !d.adopted.empty();
  Calibration cal = MakeCalibration(adopt ? d.final_fit : d.base, gravity, all, source);
  // The extended fits held what the base fit held; the reasons are the base fit's.
  for (HeldMark& h : cal.held)
    for (const HeldParameter& b : d.base.held)
      if (h.reason.empty() && ParameterName(b.index) == h.name) h.reason = b.reason;
  cal.diagnosis = DiagnosisOutcome{true, d.base.residual_rms_mps2, d.noise_rms_mps2,
                                   adopt ? d.consistent : d.adopted.empty() && d.consistent,
                                   d.conclusion};
  if (!adopt) return cal;
  cal.reference = {d.context.temp_ref_c, d.context.t_ref_s};
  for (const AdoptedEffect& a : d.adopted) cal.effects.push_back(MakeEffect(a));
  // Stages: the base model, then after each adopted effect (d.stages holds their fits).
  cal.stages.clear();
  for (CalibrationCapture& c : cal.captures) c.stage_residuals_mps2.clear();
  for (size_t s = 0; s < d.stages.size(); ++s) {
    const FitSummary& fit = d.stages[s];
    cal.stages.push_back({s == 0 ? "base model" : "+ " + d.adopted[s - 1].name, fit.residual_rms_mps2});
    for (CalibrationCapture& c : cal.captures) {
      const CaptureResidual* r = c.used ? ResidualOf(fit, c.id) : nullptr;
      c.stage_residuals_mps2.push_back(r != nullptr ? r->residual_mps2 : kNaN);
    }
  }
  return cal;
}

}  // namespace accelcal
