#include "accelcal/report/report_model.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/calibration/diagnosis/extended_model.h"
#include "accelcal/base/error.h"
#include "accelcal/calibration/fit/calibration_fit.h"
#include "accelcal/calibration/fit/fit_capture.h"
#include "accelcal/calibration/fit/least_squares.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal {
namespace {

using nlohmann::json;

[[noreturn]] void Fail(const std::string& source, const std::string& field, const std::string& what) {
  throw InputError(source, 0, 0, fmt::format("field '{}': {}", field, what));
}

// A finite number, or NaN when the key is absent or null.
double OptionalFinite(const json& j, const std::string& key, const std::string& path,
                      const std::string& source) {
  if (!j.contains(key) || j.at(key).is_null()) return kNaN;
  const json& v = j.at(key);
  if (!v.is_number() || !std::isfinite(v.get<double>())) Fail(source, path + key, "must be a finite number");
  return v.get<double>();
}

// An array of finite numbers; with `null_ok`, null entries (a point the analysis could not
// give, as `accelcal allan` writes them) become NaN.
std::vector<double> NumberArray(const json& j, const std::string& key, const std::string& path,
                                const std::string& source, bool null_ok) {
  std::vector<double> out;
  if (!j.contains(key) || j.at(key).is_null()) return out;
  const json& a = j.at(key);
  if (!a.is_array()) Fail(source, path + key, "must be an array of numbers");
  for (size_t i = 0; i < a.size(); ++i) {
    if (null_ok && a[i].is_null()) {
      out.push_back(kNaN);
      continue;
    }
    if (!a[i].is_number() || !std::isfinite(a[i].get<double>()))
      Fail(source, fmt::format("{}{}[{}]", path, key, i), "must be a finite number");
    out.push_back(a[i].get<double>());
  }
  return out;
}

std::string ReadUnit(const json& j, const std::string& source) {
  if (!j.is_object()) throw InputError(source, 0, 0, "not a JSON object");
  if (!j.contains("unit") || !j["unit"].is_string()) Fail(source, "unit", "missing (\"counts\" or \"m/s^2\")");
  const std::string unit = j["unit"].get<std::string>();
  if (unit != "counts" && unit != "m/s^2") Fail(source, "unit", "is \"" + unit + "\", expected \"counts\" or \"m/s^2\"");
  return unit;
}

const json& ReadAxes(const json& j, const std::string& source) {
  if (!j.contains("axes") || !j["axes"].is_object()) Fail(source, "axes", "missing (an object with x, y, z)");
  const json& axes = j["axes"];
  for (const auto& [key, value] : axes.items())
    if (key != "x" && key != "y" && key != "z") Fail(source, "axes." + key, "unknown axis (x, y or z)");
  if (axes.empty()) Fail(source, "axes", "has no axis");
  return axes;
}

constexpr const char* kAxisNames[3] = {"x", "y", "z"};

// Calls fn(index, axis object, "axes.x.") for each of x, y, z present in `axes`; an axis that is
// not an object is refused.
template <typename Fn>
void ForEachAxis(const json& axes, const std::string& source, Fn&& fn) {
  for (int i = 0; i < 3; ++i) {
    if (!axes.contains(kAxisNames[i])) continue;
    const json& x = axes[kAxisNames[i]];
    const std::string path = fmt::format("axes.{}.", kAxisNames[i]);
    if (!x.is_object()) Fail(source, path, "must be an object");
    fn(i, x, path);
  }
}

json Num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

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
    out.push_back({std::string(ParameterName(i)), std::string(ParameterUnit(i)), value(i), sigma(i)});
  return out;
}

void ReadFitStats(const json& fit, ReportModel* m) {
  if (!fit.is_object()) return;
  if (fit.contains("termination") && fit["termination"].is_string()) m->termination = fit["termination"];
  if (fit.contains("optimizer") && fit["optimizer"].is_string()) m->optimizer = fit["optimizer"];
  if (fit.contains("captures_used") && fit["captures_used"].is_number_integer()) m->captures_used = fit["captures_used"];
  if (fit.contains("dof") && fit["dof"].is_number_integer()) m->dof = fit["dof"];
  if (fit.contains("chi2_per_dof") && fit["chi2_per_dof"].is_number()) m->chi2_per_dof = fit["chi2_per_dof"];
  if (fit.contains("condition_number") && fit["condition_number"].is_number()) m->condition_number = fit["condition_number"];
  if (fit.contains("warnings") && fit["warnings"].is_array())
    for (const json& w : fit["warnings"])
      if (w.is_string()) m->warnings.push_back(w.get<std::string>());
}

double JsonNumber(const json& j, const char* key) {
  return (j.contains(key) && j[key].is_number()) ? j[key].get<double>() : kNaN;
}

std::string JsonString(const json& j, const char* key, const std::string& fallback) {
  return (j.contains(key) && j[key].is_string()) ? j[key].get<std::string>() : fallback;
}

// Effects come from the calibration file, which CalibrationFromJson reads loosely here: a field
// of the wrong type shows as absent ("-"), never as an exception or a made-up number.
ReportEffect ReadEffect(const json& e) {
  ReportEffect r;
  r.name = JsonString(e, "name", "?");
  r.rms_before_mps2 = JsonNumber(e, "rms_before_mps2");
  r.rms_after_mps2 = JsonNumber(e, "rms_after_mps2");
  r.chi2_per_dof_before = JsonNumber(e, "chi2_per_dof_before");
  r.chi2_per_dof_after = JsonNumber(e, "chi2_per_dof_after");
  r.corrects_readings = e.contains("corrects_readings") && e["corrects_readings"].is_boolean() &&
                        e["corrects_readings"].get<bool>();
  r.evidence = JsonString(e, "evidence", "");
  const json params = e.contains("parameters") ? e["parameters"] : json::array();
  const json sigmas = e.contains("uncertainty") ? e["uncertainty"] : json::array();
  const json units = e.contains("units") ? e["units"] : json::array();
  // "parameters" is a list of values or an object name -> value (both shapes are read).
  if (params.is_object()) {
    for (const auto& [name, value] : params.items()) {
      ReportParameter p{name, "", value.is_number() ? value.get<double>() : kNaN, kNaN};
      if (sigmas.is_object() && sigmas.contains(name) && sigmas[name].is_number()) p.sigma = sigmas[name];
      if (units.is_object() && units.contains(name) && units[name].is_string()) p.unit = units[name];
      r.parameters.push_back(p);
    }
  } else if (params.is_array()) {
    for (size_t i = 0; i < params.size(); ++i) {
      ReportParameter p{fmt::format("p{}", i), "", params[i].is_number() ? params[i].get<double>() : kNaN, kNaN};
      if (sigmas.is_array() && i < sigmas.size() && sigmas[i].is_number()) p.sigma = sigmas[i];
      if (units.is_array() && i < units.size() && units[i].is_string()) p.unit = units[i];
      r.parameters.push_back(p);
    }
  }
  return r;
}

// Per-capture residuals of the base model and after each adopted effect, refitted from the
// session's captures the calibration used (the same sequence the diagnosis ran).
std::vector<ResidualStage> RefitStages(const ReportInputs& in, const std::vector<ReportCapture>& rows) {
  std::vector<FitCapture> used;
  for (const Capture& c : in.captures)
    for (const ReportCapture& r : rows)
      if (r.record.id == c.id && r.record.used) used.push_back(MakeFitCapture(c));
  std::vector<ResidualStage> stages;
  if (used.empty()) return stages;
  FitOptions options;
  options.gravity = in.calibration.gravity;
  FitSummary fit = FitCalibration(used, options);
  auto stage_of = [&](const std::string& name, const FitSummary& s) {
    ResidualStage st;
    st.name = name;
    for (const ReportCapture& r : rows) {
      double v = kNaN;
      for (const CaptureResidual& res : s.residuals)
        if (res.id == r.record.id) v = res.residual_mps2;
      st.residual_mps2.push_back(v);
    }
    st.rms_mps2 = s.residual_rms_mps2;
    return st;
  };
  if (!fit.IsUsable()) return stages;
  stages.push_back(stage_of("base model", fit));
  std::vector<const Effect*> effects;
  const EffectContext ctx = MakeEffectContext(used, options.gravity.gravity_mps2);
  LeastSquaresOptions solver = options.solver;
  solver.gravity_mps2 = options.gravity.gravity_mps2;
  for (const json& e : in.calibration.effects) {
    const std::string name = e.is_object() ? JsonString(e, "name", "") : "";
    const Effect* effect = FindEffect(name);
    if (effect == nullptr) throw InputError(in.calibration.source, 0, 0, "unknown effect '" + name + "'");
    effects.push_back(effect);
    const ExtendedResidualModel model(effects, ctx);
    Eigen::VectorXd start = Eigen::VectorXd::Zero(model.NumParameters());
    start.head(fit.parameters.size()) = fit.parameters;
    const FitSummary next = SolveWeightedLeastSquares(model, used, start, solver);
    if (!next.IsUsable()) break;
    fit = next;
    stages.push_back(stage_of("+ " + name, fit));
  }
  return stages;
}

ReportCapture MakeRow(const CaptureRecord& rec, const std::vector<Capture>& captures) {
  ReportCapture row;
  row.record = rec;
  for (const Capture& c : captures) {
    if (c.id != rec.id || c.samples.empty()) continue;
    const CaptureStats stats = ComputeStats(c.samples);
    if (stats.n > 1) row.noise_counts = std::sqrt(stats.StdCounts().squaredNorm() / 3.0);
    row.temp_min_c = stats.min_temp_c;
    row.temp_max_c = stats.max_temp_c;
  }
  return row;
}

void AddCheck(ReportModel* m, std::string what, std::string unit, double value, double limit,
              bool at_least) {
  if (!std::isfinite(limit)) return;
  LimitCheck c{std::move(what), std::move(unit), value, limit, at_least, false};
  c.pass = std::isfinite(value) && (at_least ? value >= limit : value <= limit);
  m->checks.push_back(c);
}

void CheckLimits(const ProcedureLimits& l, const Calibration& cal, ReportModel* m) {
  if (l.min_captures > 0)
    AddCheck(m, "captures used by the fit", "", m->captures_used, l.min_captures, true);
  AddCheck(m, "residual RMS", "m/s^2", m->residual_rms_mps2, l.max_residual_rms_mps2, false);
  AddCheck(m, "residual RMS / noise RMS", "", m->residual_rms_mps2 / m->noise_rms_mps2,
           l.max_residual_rms_noise, false);
  AddCheck(m, "largest bias 1-sigma", "counts", cal.uncertainty.bias_counts.maxCoeff(),
           l.max_bias_sigma_counts, false);
  const Eigen::Vector3d rel = cal.uncertainty.scale_counts_per_mps2.cwiseQuotient(cal.model.scale_counts_per_mps2);
  AddCheck(m, "largest scale 1-sigma", "ppm", rel.maxCoeff() * 1e6, l.max_scale_sigma_ppm, false);
  const double mis = std::max({cal.uncertainty.a_yz_rad, cal.uncertainty.a_zy_rad, cal.uncertainty.a_zx_rad});
  AddCheck(m, "largest misalignment 1-sigma", "rad", mis, l.max_misalignment_sigma_rad, false);
}

}  // namespace

std::string_view VerdictToString(Verdict v) {
  switch (v) {
    case Verdict::kPass: return "PASS";
    case Verdict::kFail: return "FAIL";
    case Verdict::kNoLimits: return "NO LIMITS STATED";
  }
  return "?";
}

AllanSection ParseAllanJson(const json& j, const std::string& source) {
  AllanSection a;
  a.source = source;
  a.unit = ReadUnit(j, source);
  a.rate_hz = OptionalFinite(j, "rate_hz", "", source);
  ForEachAxis(ReadAxes(j, source), source, [&](int i, const json& x, const std::string& path) {
    AllanAxis ax;
    ax.noise_density = OptionalFinite(x, "noise_density", path, source);
    ax.bias_instability = OptionalFinite(x, "bias_instability", path, source);
    ax.random_walk = OptionalFinite(x, "random_walk", path, source);
    ax.max_drift = OptionalFinite(x, "max_drift", path, source);
    ax.tau_s = NumberArray(x, "tau_s", path, source, false);
    ax.adev = NumberArray(x, "adev", path, source, true);
    ax.adev_lo = NumberArray(x, "adev_lo", path, source, true);
    ax.adev_hi = NumberArray(x, "adev_hi", path, source, true);
    if (ax.adev.size() != ax.tau_s.size()) Fail(source, path + "adev", "must have as many values as tau_s");
    if (!ax.adev_lo.empty() && ax.adev_lo.size() != ax.tau_s.size())
      Fail(source, path + "adev_lo", "must have as many values as tau_s");
    if (!ax.adev_hi.empty() && ax.adev_hi.size() != ax.tau_s.size())
      Fail(source, path + "adev_hi", "must have as many values as tau_s");
    for (size_t k = 0; k < ax.tau_s.size(); ++k)
      if (ax.tau_s[k] <= 0.0 || ax.adev[k] <= 0.0)  // false for a NaN (null) adev
        Fail(source, fmt::format("{}tau_s[{}]", path, k), "tau and adev must be positive (log axes)");
    a.axes[i] = ax;
  });
  return a;
}

// `accelcal noise -o FILE` (format "accelcal-noise/1"): the first record's std and density,
// and the bias repeatability (std of the records' means) when there are several records.
NoiseSection ParseNoiseReportJson(const json& j, const std::string& source) {
  NoiseSection n;
  n.unit = ReadUnit(j, source);
  const json& records = j["records"];
  if (!records.is_array() || records.empty() || !records[0].is_object())
    Fail(source, "records", "must be a non-empty array of records");
  n.source = records.size() > 1 ? fmt::format("{}, record 1 of {}", source, records.size()) : source;
  const json& axes = ReadAxes(records[0], source);
  std::vector<double> repeat;
  if (j.contains("repeatability") && j["repeatability"].is_object())
    repeat = NumberArray(j["repeatability"], "std_of_means", "repeatability.", source, true);
  for (int i = 0; i < 3; ++i) {
    if (!axes.contains(kAxisNames[i])) continue;
    const std::string path = fmt::format("records[0].axes.{}.", kAxisNames[i]);
    const json& x = axes[kAxisNames[i]];
    if (!x.is_object()) Fail(source, path, "must be an object");
    NoiseAxis ax;
    ax.std = OptionalFinite(x, "std", path, source);
    ax.noise_density = OptionalFinite(x, "density", path, source);
    if (repeat.size() == 3) ax.bias_repeatability = repeat[static_cast<size_t>(i)];
    n.axes[i] = ax;
  }
  return n;
}

NoiseSection ParseNoiseJson(const json& j, const std::string& source) {
  if (j.is_object() && j.contains("records") && !j.contains("axes")) return ParseNoiseReportJson(j, source);
  NoiseSection n;
  n.source = source;
  n.unit = ReadUnit(j, source);
  ForEachAxis(ReadAxes(j, source), source, [&](int i, const json& x, const std::string& path) {
    NoiseAxis ax;
    ax.std = OptionalFinite(x, "std", path, source);
    ax.noise_density = OptionalFinite(x, "noise_density", path, source);
    ax.bias_repeatability = OptionalFinite(x, "bias_repeatability", path, source);
    n.axes[i] = ax;
  });
  return n;
}

json AllanToJson(const AllanSection& a) {
  json axes = json::object();
  for (int i = 0; i < 3; ++i) {
    if (!a.axes[i]) continue;
    const AllanAxis& x = *a.axes[i];
    axes[kAxisNames[i]] = {{"noise_density", Num(x.noise_density)}, {"bias_instability", Num(x.bias_instability)},
                           {"random_walk", Num(x.random_walk)},     {"max_drift", Num(x.max_drift)},
                           {"tau_s", x.tau_s},                      {"adev", x.adev},
                           {"adev_lo", x.adev_lo},                  {"adev_hi", x.adev_hi}};
  }
  return {{"unit", a.unit}, {"rate_hz", Num(a.rate_hz)}, {"axes", axes}, {"source", a.source}};
}

json NoiseToJson(const NoiseSection& n) {
  json axes = json::object();
  for (int i = 0; i < 3; ++i) {
    if (!n.axes[i]) continue;
    const NoiseAxis& x = *n.axes[i];
    axes[kAxisNames[i]] = {{"std", Num(x.std)}, {"noise_density", Num(x.noise_density)},
                           {"bias_repeatability", Num(x.bias_repeatability)}};
  }
  return {{"unit", n.unit}, {"axes", axes}, {"source", n.source}};
}

ReportModel BuildReportModel(const ReportInputs& in) {
  const Calibration& cal = in.calibration;
  ReportModel m;
  m.meta = in.meta;
  m.gravity_text = cal.gravity.Describe();
  m.gravity_mps2 = cal.gravity.gravity_mps2;
  m.fit_source = cal.source;
  m.tool = std::string("accelcal ") + ACCELCAL_VERSION;
  m.parameters = Parameters(cal);
  ReadFitStats(cal.fit, &m);
  m.residual_rms_mps2 = cal.residual_rms_mps2;
  m.residual_max_abs_mps2 = cal.residual_max_abs_mps2;

  std::vector<double> sigmas;
  for (const CaptureRecord& rec : cal.captures) {
    m.captures.push_back(MakeRow(rec, in.captures));
    if (!rec.used) ++m.captures_left_out;
    if (rec.used) sigmas.push_back(rec.sigma_mps2);
  }
  if (m.captures_used == 0) m.captures_used = static_cast<int>(sigmas.size());
  m.noise_rms_mps2 = Rms(sigmas);
  for (const ReportCapture& r : m.captures) {
    if (std::isfinite(r.temp_min_c)) m.temp_min_c = std::isfinite(m.temp_min_c) ? std::min(m.temp_min_c, r.temp_min_c) : r.temp_min_c;
    if (std::isfinite(r.temp_max_c)) m.temp_max_c = std::isfinite(m.temp_max_c) ? std::max(m.temp_max_c, r.temp_max_c) : r.temp_max_c;
  }

  for (const json& e : cal.effects)
    if (e.is_object()) m.effects.push_back(ReadEffect(e));
  if (!in.captures.empty()) m.stages = RefitStages(in, m.captures);
  if (m.stages.empty()) {
    // A file alone: only the adopted model's residuals are known.
    ResidualStage final_stage;
    final_stage.name = m.effects.empty() ? "base model" : "with adopted effects";
    for (const ReportCapture& r : m.captures) final_stage.residual_mps2.push_back(r.record.residual_mps2);
    final_stage.rms_mps2 = m.residual_rms_mps2;
    m.stages.push_back(final_stage);
  }

  m.noise = in.noise;
  m.allan = in.allan;
  if (in.limits && in.limits->Any()) {
    CheckLimits(*in.limits, cal, &m);
    const bool all = std::all_of(m.checks.begin(), m.checks.end(), [](const LimitCheck& c) { return c.pass; });
    m.verdict = all ? Verdict::kPass : Verdict::kFail;
  }
  return m;
}

void FillMetaFromInputs(const std::map<std::string, std::map<std::string, std::string>>& inputs,
                        ReportMeta* meta) {
  for (const auto& [step, values] : inputs) {
    if (auto it = values.find("device"); it != values.end()) meta->device = it->second;
    if (auto it = values.find("operator"); it != values.end()) meta->operator_name = it->second;
    if (auto it = values.find("place"); it != values.end()) meta->place = it->second;
  }
}

void ReadAnalysesFromResult(const json& result, const std::string& source, ReportInputs* inputs) {
  if (result.contains("allan") && !result["allan"].is_null())
    inputs->allan = ParseAllanJson(result["allan"], source + " (result key allan)");
  if (result.contains("noise") && !result["noise"].is_null())
    inputs->noise = ParseNoiseJson(result["noise"], source + " (result key noise)");
}

ReportInputs ReportInputsFromJournal(const SessionJournal& journal, const std::string& source_name) {
  const std::optional<json> result = journal.Result();
  if (!result) throw Error(fmt::format("session {} has no calibration yet", source_name));
  ReportInputs in;
  in.calibration = CalibrationFromJson(*result, source_name);
  for (JournalCapture& c : journal.Captures()) in.captures.push_back(std::move(c.capture));
  FillMetaFromInputs(journal.Inputs(), &in.meta);
  ReadAnalysesFromResult(*result, source_name, &in);
  return in;
}

}  // namespace accelcal
