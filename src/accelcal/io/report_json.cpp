#include "accelcal/io/report_json.h"

#include <cmath>

#include "accelcal/io/detail/budget_json.h"
#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/detail/json_values.h"

namespace accelcal {
namespace {

using namespace detail;  // the JSON helpers

json Num(double v) { return JsonNumber(v); }

json Parameters(const std::vector<ReportParameter>& params) {
  json a = json::array();
  for (const ReportParameter& p : params)
    a.push_back({{"name", p.name}, {"unit", p.unit}, {"value", Num(p.value)}, {"sigma", Num(p.sigma)}, {"held", p.held}});
  return a;
}

json Captures(const std::vector<ReportCapture>& captures) {
  json a = json::array();
  for (const ReportCapture& c : captures) {
    const CalibrationCapture& r = c.record;
    a.push_back({{"id", r.id},
                 {"label", r.label},
                 {"kind", std::string(CaptureKindToString(r.kind))},
                 {"used", r.used},
                 {"reason", r.used ? json(nullptr) : json(r.reason)},
                 {"n_samples", r.n_samples},
                 {"radius_m", Num(r.radius_m)},
                 {"rpm", Num(r.rpm)},
                 {"noise_counts", Num(c.noise_counts)},
                 {"temp_min_c", Num(c.temp_min_c)},
                 {"temp_max_c", Num(c.temp_max_c)},
                 {"reference_mps2", Num(r.reference_mps2)},
                 {"magnitude_mps2", Num(c.magnitude_mps2())},
                 {"residual_mps2", Num(r.residual_mps2)},
                 {"sigma_mps2", Num(r.sigma_mps2)}});
  }
  return a;
}

json Effects(const std::vector<ReportEffect>& effects) {
  json a = json::array();
  for (const ReportEffect& e : effects)
    a.push_back({{"name", e.name},
                 {"rms_before_mps2", Num(e.rms_before_mps2)},
                 {"rms_after_mps2", Num(e.rms_after_mps2)},
                 {"chi2_per_dof_before", Num(e.chi2_per_dof_before)},
                 {"chi2_per_dof_after", Num(e.chi2_per_dof_after)},
                 {"corrects_readings", e.corrects_readings},
                 {"evidence", e.evidence},
                 {"parameters", Parameters(e.parameters)}});
  return a;
}

json Stages(const std::vector<ResidualStage>& stages) {
  json a = json::array();
  for (const ResidualStage& s : stages)
    a.push_back({{"name", s.name}, {"rms_mps2", Num(s.rms_mps2)}, {"residual_mps2", JsonNumbers(s.residual_mps2)}});
  return a;
}

// "not recorded" is null in JSON.
json Text(const std::string& s) { return s.empty() ? json(nullptr) : json(s); }

json Checks(const ReportModel& m) {
  json a = json::array();
  for (const LimitCheck& c : m.checks)
    a.push_back({{"what", c.what}, {"unit", c.unit}, {"value", Num(c.value)}, {"limit", Num(c.limit)},
                 {"at_least", c.at_least}, {"pass", c.pass}, {"parameter", Text(c.parameter)},
                 {"rule", Text(c.rule)}, {"why", Text(c.why)}, {"on_uncertainty", c.on_uncertainty}});
  return a;
}

json BenchSecondsJson(const BenchSeconds& b) {
  return {{"capture_s", Num(b.capture_s)},
          {"settle_s", Num(b.settle_s)},
          {"handling_s", Num(b.handling_s)},
          {"total_s", Num(b.TotalS())}};
}

// The session's bench time (spent: on the virtual bench its handling model, on a real bench
// the session's clock), the plan's, and the planned and reached U(k=2) per parameter.
json BenchTimeJson(const ReportBenchTime& b) {
  json out = BenchSecondsJson(b.spent);
  out["captures"] = b.captures;
  out["planned_by"] = b.planned_by;
  out["planned"] = BenchSecondsJson(b.planned);
  json parameters = json::array();
  for (const BenchParameterU& p : b.parameters)
    parameters.push_back({{"name", p.name},
                          {"target_U", Num(p.target)},
                          {"planned_U", Num(p.planned)},
                          {"reached_U", Num(p.reached)}});
  out["uncertainty"] = parameters;
  return out;
}

// The certificate's statements (its results are the budget's and the parameters').
json CertificateJson(const Certificate& c) {
  json results = json::array();
  for (const CertificateResult& r : c.results)
    results.push_back({{"name", r.name}, {"quantity", r.quantity}, {"forms", r.forms},
                       {"coverage_factor", Num(r.coverage_factor)}, {"held", r.held}});
  json equipment = json::array();
  for (const EquipmentItem& e : c.equipment)
    equipment.push_back({{"role", std::string(InfoOf(e.role).key)}, {"name", e.name},
                         {"id", e.identification}, {"standard_uncertainty_si", Num(e.standard_uncertainty)},
                         {"traceability", e.traceability}});
  return {{"number", c.number}, {"simulated", c.simulated}, {"method", c.method},
          {"equipment", equipment}, {"ambient", c.ambient}, {"results", results},
          {"coverage", c.coverage}, {"not_stated", c.not_stated}, {"traceability", c.traceability},
          {"decision_rule", c.decision_rule}, {"conformity", c.conformity}};
}

}  // namespace


json ReportToJson(const ReportModel& m) {
  json warnings = json::array();
  for (const std::string& w : m.warnings) warnings.push_back(w);
  return {{"format", kReportFormat},
          {"tool", m.tool},
          {"device", Text(m.meta.device)},
          {"operator", Text(m.meta.operator_name)},
          {"date_utc", Text(m.meta.date_utc)},
          {"place", Text(m.meta.place)},
          {"session", {{"name", Text(m.meta.session_name)}, {"path", Text(m.meta.session_path)}}},
          {"procedure", Text(m.meta.procedure)},
          {"source", Text(m.meta.source)},
          {"history", m.meta.history},
          {"fitted_from", Text(m.fit_source)},
          {"gravity", {{"value_mps2", Num(m.gravity_mps2)}, {"description", m.gravity_text}}},
          {"parameters", Parameters(m.parameters)},
          {"parameter_notes", m.parameter_notes},
          {"diagnosis_conclusion", Text(m.diagnosis_conclusion)},
          {"fit",
           {{"termination", Text(m.termination)},
            {"optimizer", Text(m.optimizer)},
            {"captures_used", m.captures_used},
            {"captures_left_out", m.captures_left_out},
            {"dof", m.dof},
            {"chi2_per_dof", Num(m.chi2_per_dof)},
            {"condition_number", Num(m.condition_number)},
            {"warnings", warnings}}},
          {"residuals",
           {{"rms_mps2", Num(m.residual_rms_mps2)},
            {"max_abs_mps2", Num(m.residual_max_abs_mps2)},
            {"noise_rms_mps2", Num(m.noise_rms_mps2)},
            {"stages", Stages(m.stages)}}},
          {"captures", Captures(m.captures)},
          {"effects", Effects(m.effects)},
          {"temperature_c", {{"min", Num(m.temp_min_c)}, {"max", Num(m.temp_max_c)}}},
          {"noise", m.noise ? NoiseToJson(*m.noise) : json(nullptr)},
          {"allan", m.allan ? AllanToJson(*m.allan) : json(nullptr)},
          {"limits", Checks(m)},
          {"session_gaps", m.gaps ? SessionGapsToJson(*m.gaps) : json(nullptr)},
          {"incomplete", m.incomplete},
          {"verdict", std::string(VerdictToString(m.verdict))},
          {"uncertainty_budget", m.budget ? detail::BudgetToJson(*m.budget) : json(nullptr)},
          {"certificate", CertificateJson(m.certificate)},
          {"bench_time", m.bench_time ? BenchTimeJson(*m.bench_time) : json(nullptr)}};
}

std::string ReportJsonText(const ReportModel& model) { return detail::JsonText(ReportToJson(model)) + "\n"; }

}  // namespace accelcal
