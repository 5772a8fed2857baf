#include "accelcal/report/report_model.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>
#include <fmt/format.h>

#include "accelcal/base/error.h"
#include "accelcal/base/version.h"
#include "accelcal/base/sensor_model.h"
#include "accelcal/session/session_inputs.h"
#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/report/completeness.h"
#include "accelcal/report/limit_checks.h"

namespace accelcal {
namespace {

double Rms(const std::vector<double>& v) {
  double sum = 0.0;
  int n = 0;
  for (double x : v)
    if (std::isfinite(x)) { sum += x * x; ++n; }
  return n > 0 ? std::sqrt(sum / n) : kNaN;
}

std::vector<ReportParameter> Parameters(const Calibration& cal) {
  std::vector<ReportParameter> out;
  const Eigen::Matrix<double, kNumBaseParameters, 1> value = cal.model.ToVector();
  const Eigen::Matrix<double, kNumBaseParameters, 1> sigma = cal.uncertainty.ToVector();
  for (int i = 0; i < kNumBaseParameters; ++i)
    out.push_back({std::string(ParameterName(i)), std::string(ParameterUnit(i)), value(i), sigma(i),
                   cal.FindHeld(i) != nullptr, CertificateExpandedUncertainty(cal, i)});
  return out;
}

ReportEffect MakeReportEffect(const CalibrationEffect& e) {
  ReportEffect r;
  r.name = e.name;
  r.rms_before_mps2 = e.rms_before_mps2;
  r.rms_after_mps2 = e.rms_after_mps2;
  r.chi2_per_dof_before = e.chi2_per_dof_before;
  r.chi2_per_dof_after = e.chi2_per_dof_after;
  r.corrects_readings = e.corrects_readings;
  r.evidence = e.evidence;
  for (const EffectParameter& p : e.parameters) r.parameters.push_back({p.name, p.unit, p.value, p.sigma});
  return r;
}

// The residuals of every capture under each stage of the model, as the calibration states them;
// a calibration that does not state its stages (an older file) has only the final ones.
std::vector<ResidualStage> Stages(const Calibration& cal, const std::vector<ReportCapture>& rows) {
  std::vector<ResidualStage> stages;
  const bool known = !cal.stages.empty() &&
                     std::all_of(cal.captures.begin(), cal.captures.end(), [&](const CalibrationCapture& c) {
                       return c.stage_residuals_mps2.size() == cal.stages.size();
                     });
  if (!known) {
    ResidualStage final_stage;
    final_stage.name = cal.effects.empty() ? "base model" : "with adopted effects";
    for (const ReportCapture& r : rows) final_stage.residual_mps2.push_back(r.record.residual_mps2);
    final_stage.rms_mps2 = cal.residual_rms_mps2;
    stages.push_back(final_stage);
    return stages;
  }
  for (size_t k = 0; k < cal.stages.size(); ++k) {
    ResidualStage st;
    st.name = cal.stages[k].name;
    st.rms_mps2 = cal.stages[k].rms_mps2;
    for (const ReportCapture& r : rows) st.residual_mps2.push_back(r.record.stage_residuals_mps2[k]);
    stages.push_back(st);
  }
  return stages;
}

ReportCapture MakeRow(const CalibrationCapture& rec, const std::vector<ReportCaptureStats>& captures) {
  ReportCapture row;
  row.record = rec;
  for (const ReportCaptureStats& c : captures) {
    if (c.id != rec.id || c.stats.n == 0) continue;
    const CaptureStats& stats = c.stats;
    if (stats.n > 1) row.noise_counts = std::sqrt(stats.StdCounts().squaredNorm() / 3.0);
    row.temp_min_c = stats.min_temp_c;
    row.temp_max_c = stats.max_temp_c;
  }
  return row;
}

}  // namespace

std::vector<std::string> ParameterNotes(const std::vector<std::string>& effect_names) {
  std::vector<std::string> notes = {
      "What the nine parameters are: b is each axis's reading at zero specific force and K its "
      "sensitivity; the three angles of T turn the sensor's axes into an orthogonal platform "
      "frame whose x is the sensor's x axis and whose y lies in the sensor's x-y plane.",
      "What they cannot resolve: the fit matches magnitudes |a|, and a rotation does not change "
      "a magnitude. The sensor's orientation on its mount (a mounting rotation) is therefore not "
      "measured, and a misalignment of another form (a lower-triangular one, axes referred to z "
      "rather than x) is absorbed into magnitude-equivalent angles: the calibrated |a| is right, "
      "but the angles are not the physical angles between the axes and the directions of a are "
      "known only up to a rotation. Align the platform to the vehicle's frame separately when "
      "directions matter."};
  for (const std::string& name : effect_names)
    if (const Effect* effect = FindEffect(name); effect != nullptr && !effect->ReportNote().empty())
      notes.push_back(fmt::format("{}: {}", name, effect->ReportNote()));
  return notes;
}

std::string_view VerdictToString(Verdict v) {
  switch (v) {
    case Verdict::kPass: return "PASS";
    case Verdict::kFail: return "FAIL";
    case Verdict::kNoLimits: return "NO LIMITS STATED";
    case Verdict::kIncomplete: return "INCOMPLETE";
  }
  return "?";
}

bool TakesGravityErrorForItsOwn(const std::string& effect_name) {
  const Effect* effect = FindEffect(effect_name);
  return effect != nullptr && effect->TakesGravityErrorForItsOwn();
}

std::string GravityAmbiguityNote(const GravitySpec& gravity, const std::vector<std::string>& effect_names) {
  std::vector<std::string> found;
  for (const std::string& n : effect_names)
    if (TakesGravityErrorForItsOwn(n)) found.push_back(n);
  if (found.empty()) return "";
  if (gravity.is_standard())
    return fmt::format(
        "{} found while gravity is the standard value, not this place's: a local gravity other "
        "than 9.80665 m/s^2 gives the same signature (static and turntable captures see only "
        "w^2 r / g), so the data cannot tell a gravity error from a speed or radius error. Check "
        "both: the local gravity (a measured value, or the place's latitude and altitude) and the "
        "turntable (its speed with a tachometer, its radius with a ruler).",
        fmt::join(found, " and "));
  // Whatever the gravity's source: a wrong place typed, a measured value mistyped, an anomaly.
  return fmt::format(
      "{} found: a local gravity other than the one used ({}) gives the same signature (static "
      "and turntable captures see only w^2 r / g), so the data cannot tell a gravity error from a "
      "speed or radius error. Check both: the local gravity (the place typed, or a measured value) "
      "and the turntable (its speed with a tachometer, its radius with a ruler); a verified "
      "turntable leaves the gravity to blame.",
      fmt::join(found, " and "), gravity.Describe());
}

ReportCaptureStats ReportStatsOf(const Capture& capture) { return {capture.id, capture.stats()}; }

std::vector<ReportCaptureStats> ReportStatsOf(const std::vector<Capture>& captures) {
  std::vector<ReportCaptureStats> out;
  out.reserve(captures.size());
  for (const Capture& c : captures) out.push_back(ReportStatsOf(c));
  return out;
}

ReportModel BuildReportModel(const ReportInputs& in) {
  const Calibration& cal = in.calibration;
  ReportModel m;
  m.meta = in.meta;
  m.gravity_text = cal.gravity.Describe();
  m.gravity_mps2 = cal.gravity.gravity_mps2;
  m.fit_source = cal.source;
  m.tool = std::string("accelcal ") + kAccelcalVersion;
  m.parameters = Parameters(cal);
  m.parameter_notes = ParameterNotes(cal.EffectNames());
  m.termination = cal.fit.termination == FitTermination::kNotRun
                      ? std::string() : std::string(FitTerminationToString(cal.fit.termination));
  m.optimizer = cal.fit.optimizer;
  m.captures_used = cal.fit.captures_used;
  m.dof = cal.fit.dof;
  // chi2/dof is undefined with no degrees of freedom (the fit writes -1 or 0/0 there): NaN,
  // which the reports show as "-", never "-1.000".
  m.chi2_per_dof = cal.fit.dof > 0 && cal.fit.chi2_per_dof >= 0.0 ? cal.fit.chi2_per_dof : kNaN;
  m.condition_number = cal.fit.condition_number;
  m.warnings = cal.fit.warnings;
  for (const HeldMark& h : cal.held)
    m.warnings.push_back(fmt::format("{} held at {} (not fitted): {}", h.name, h.value, h.reason));
  m.residual_rms_mps2 = cal.residual_rms_mps2;
  m.residual_max_abs_mps2 = cal.residual_max_abs_mps2;

  std::vector<double> sigmas;
  for (const CalibrationCapture& rec : cal.captures) {
    m.captures.push_back(MakeRow(rec, in.captures));
    if (!rec.used) ++m.captures_left_out;
    if (rec.used) sigmas.push_back(rec.sigma_mps2);
  }
  if (m.captures_used == 0) m.captures_used = static_cast<int>(sigmas.size());
  m.noise_rms_mps2 = Rms(sigmas);
  if (cal.budget)
    for (const ParameterBudget& p : cal.budget->parameters)
      for (const BudgetContribution& b : p.contributions)
        m.sigma_has_own_radius = m.sigma_has_own_radius || b.quantity == kOwnRadiusQuantity;
  for (const ReportCapture& r : m.captures) {
    if (std::isfinite(r.temp_min_c)) m.temp_min_c = std::isfinite(m.temp_min_c) ? std::min(m.temp_min_c, r.temp_min_c) : r.temp_min_c;
    if (std::isfinite(r.temp_max_c)) m.temp_max_c = std::isfinite(m.temp_max_c) ? std::max(m.temp_max_c, r.temp_max_c) : r.temp_max_c;
  }

  for (const CalibrationEffect& e : cal.effects) m.effects.push_back(MakeReportEffect(e));
  if (cal.diagnosis && cal.diagnosis->ran) m.diagnosis_conclusion = cal.diagnosis->conclusion;
  for (const std::string& label : RepeatedPoseLabels(cal.pose_repeats))
    m.pose_repeat_paths.push_back(DescribePoseRepeatPath(cal.pose_repeats, label));
  m.stages = Stages(cal, m.captures);

  m.noise = in.noise;
  m.allan = in.allan;
  bool all_pass = true;
  if (in.limits && in.limits->Any()) {
    m.checks = CheckProcedureLimits(*in.limits, in, m);
    all_pass = std::all_of(m.checks.begin(), m.checks.end(), [](const LimitCheck& c) { return c.pass; });
    m.verdict = all_pass ? Verdict::kPass : Verdict::kFail;
  }
  m.gaps = in.gaps;
  m.incomplete = IncompleteReasons(in, m.checks);
  if (all_pass && !m.incomplete.empty()) m.verdict = Verdict::kIncomplete;
  m.budget = cal.budget;
  m.bench_time = in.bench_time;
  if (m.bench_time && m.budget) FillReachedU(*m.budget, &*m.bench_time);
  m.certificate = MakeCertificate(in, m);
  return m;
}

void FillMetaFromInputs(const std::map<std::string, std::map<std::string, std::string>>& inputs,
                        ReportMeta* meta) {
  for (const auto& [step, values] : inputs) {
    if (auto it = values.find(welcome_key::kDevice); it != values.end()) meta->device = it->second;
    if (auto it = values.find(welcome_key::kOperator); it != values.end()) meta->operator_name = it->second;
    if (auto it = values.find(welcome_key::kPlace); it != values.end()) meta->place = it->second;
  }
}

}  // namespace accelcal
