#include "accelcal/io/calibration_file.h"

#include <algorithm>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/io/atomic_write.h"
#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/detail/json_values.h"
#include "accelcal/io/detail/budget_json.h"
#include "accelcal/io/detail/read_file.h"
#include "accelcal/base/version.h"

namespace accelcal {
namespace {

using namespace detail;  // the JSON helpers

json Misalignment(const SensorModel& m) {
  return {{"yz", JsonNumber(m.a_yz_rad)}, {"zy", JsonNumber(m.a_zy_rad)}, {"zx", JsonNumber(m.a_zx_rad)}};
}

json GravityJson(const GravitySpec& g) {
  json j = {{"source", g.SourceName()}, {"description", g.Describe()},
            {"sigma_mps2", JsonNumber(g.sigma_mps2)}};
  if (g.source == GravitySpec::Source::kWgs84) {
    j["latitude_deg"] = g.latitude_deg;
    j["altitude_m"] = g.altitude_m;
  }
  return j;
}

json CaptureJson(const CalibrationCapture& c) {
  json j = {{"id", c.id},
            {"kind", std::string(CaptureKindToString(c.kind))},
            {"label", c.label},
            {"used", c.used},
            {"reason", c.used ? json(nullptr) : json(c.reason)},
            {"n_samples", c.n_samples},
            {"residual_mps2", JsonNumber(c.residual_mps2)},
            {"reference_mps2", JsonNumber(c.reference_mps2)},
            {"sigma_mps2", JsonNumber(c.sigma_mps2)},
            {"radius_m", JsonNumber(c.radius_m)},
            {"rpm", JsonNumber(c.rpm)},
            {"t_start_s", JsonNumber(c.t_start_s)},
            {"t_end_s", JsonNumber(c.t_end_s)},
            {"mean_counts", JsonTriad(c.mean_counts)}};
  if (!c.stage_residuals_mps2.empty()) j["stage_residuals_mps2"] = JsonNumbers(c.stage_residuals_mps2);
  return j;
}

json FitJson(const Calibration& cal) {
  const FitStatistics& s = cal.fit;
  json correlated = nullptr;
  if (!s.most_correlated_first.empty())
    correlated = {{"first", s.most_correlated_first},
                  {"second", s.most_correlated_second},
                  {"rho", JsonNumber(s.most_correlated_rho)}};
  json j = {{"termination", std::string(FitTerminationToString(s.termination))},
            {"captures_used", s.captures_used},
            {"dof", s.dof},
            {"chi2", JsonNumber(s.chi2)},
            {"chi2_per_dof", JsonNumber(s.chi2_per_dof)},
            {"uncertainty_scale", JsonNumber(s.uncertainty_scale)},
            {"condition_number", JsonNumber(s.condition_number)},
            {"most_correlated", correlated},
            {"optimizer", s.optimizer},
            {"warnings", s.warnings}};
  if (cal.diagnosis)
    j["diagnosis"] = {{"ran", cal.diagnosis->ran},
                      {"base_residual_rms_mps2", JsonNumber(cal.diagnosis->base_residual_rms_mps2)},
                      {"noise_rms_mps2", JsonNumber(cal.diagnosis->noise_rms_mps2)},
                      {"consistent_with_noise", cal.diagnosis->consistent_with_noise},
                      {"conclusion", cal.diagnosis->conclusion}};
  if (s.scatter) {
    json candidates = json::array();
    for (const ScatterCandidate& c : s.scatter->candidates)
      candidates.push_back({{"structure", std::string(ScatterStructureToString(c.structure))},
                            {"size", JsonNumber(c.size)},
                            {"unit", std::string(ScatterSizeUnit(c.structure))},
                            {"log_likelihood", JsonNumber(c.log_likelihood)}});
    j["scatter"] = {{"structure", std::string(ScatterStructureToString(s.scatter->structure))},
                    {"size", JsonNumber(s.scatter->size)},
                    {"unit", std::string(ScatterSizeUnit(s.scatter->structure))},
                    {"min_dof", JsonNumber(s.scatter->min_dof)},
                    {"ratio_to_noise", JsonNumber(s.scatter->ratio_to_noise)},
                    {"candidates", candidates}};
  }
  if (!cal.stages.empty()) {
    json stages = json::array();
    for (const ModelStage& st : cal.stages)
      stages.push_back({{"name", st.name}, {"rms_mps2", JsonNumber(st.rms_mps2)}});
    j["stages"] = stages;
  }
  return j;
}

json EffectJson(const CalibrationEffect& e, const EffectReference& ref) {
  json parameters = json::object(), uncertainty = json::object(), units = json::object();
  for (const EffectParameter& p : e.parameters) {
    parameters[p.name] = JsonNumber(p.value);
    uncertainty[p.name] = JsonNumber(p.sigma);
    units[p.name] = p.unit;
  }
  return {{"name", e.name},
          {"parameters", parameters},
          {"uncertainty", uncertainty},
          {"units", units},
          {"rms_before_mps2", JsonNumber(e.rms_before_mps2)},
          {"rms_after_mps2", JsonNumber(e.rms_after_mps2)},
          {"chi2_per_dof_before", JsonNumber(e.chi2_per_dof_before)},
          {"chi2_per_dof_after", JsonNumber(e.chi2_per_dof_after)},
          {"reference", {{"temp_c", JsonNumber(ref.temp_c)}, {"t_s", JsonNumber(ref.t_s)}}},
          {"corrects_readings", e.corrects_readings},
          {"evidence", e.evidence}};
}

// --- strict reading -------------------------------------------------------------------------

Eigen::Vector3d ReadTriad(const json& j, const std::string& key, const std::string& path,
                          const std::string& source) {
  const json& v = RequiredField(j, key, path, source);
  if (!v.is_array() || v.size() != 3) FailField(source, path + key, "must be an array of 3 numbers");
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) {
    if (!v[i].is_number() || !std::isfinite(v[i].get<double>()))
      FailField(source, fmt::format("{}{}[{}]", path, key, i), "must be a finite number");
    out(i) = v[i].get<double>();
  }
  return out;
}

// [x, y, z] with null entries as NaN; absent or null as all NaN.
Eigen::Vector3d OptionalTriad(const json& j, const std::string& key, const std::string& path,
                              const std::string& source) {
  Eigen::Vector3d out = Eigen::Vector3d::Constant(NAN);
  if (!j.contains(key) || j.at(key).is_null()) return out;
  const std::vector<double> v = NumberArray(j, key, path, source, true);
  if (v.size() != 3) FailField(source, path + key, "must be an array of 3 numbers");
  for (int i = 0; i < 3; ++i) out(i) = v[static_cast<size_t>(i)];
  return out;
}

SensorModel ReadModel(const json& j, const std::string& path, const std::string& source) {
  SensorModel m;
  m.bias_counts = ReadTriad(j, "bias_counts", path, source);
  m.scale_counts_per_mps2 = ReadTriad(j, "scale_counts_per_mps2", path, source);
  const json& mis = RequiredField(j, "misalignment_rad", path, source);
  m.a_yz_rad = RequiredFinite(mis, "yz", path + "misalignment_rad.", source);
  m.a_zy_rad = RequiredFinite(mis, "zy", path + "misalignment_rad.", source);
  m.a_zx_rad = RequiredFinite(mis, "zx", path + "misalignment_rad.", source);
  return m;
}

// Parameters held in a reduced model (calibration.h): absent or empty when all nine were fitted.
std::vector<HeldMark> ReadHeld(const json& j, const std::string& source) {
  std::vector<HeldMark> out;
  if (!j.contains("held") || j.at("held").is_null()) return out;
  const json& held = j.at("held");
  if (!held.is_array()) FailField(source, "held", "must be an array");
  for (size_t i = 0; i < held.size(); ++i) {
    const std::string path = fmt::format("held[{}].", i);
    if (!held[i].is_object()) FailField(source, fmt::format("held[{}]", i), "must be an object");
    HeldMark h;
    h.name = OptionalString(held[i], "name", path, source);
    if (h.name != "a_yz" && h.name != "a_zy" && h.name != "a_zx")
      FailField(source, path + "name", "must be one of the misalignment angles a_yz, a_zy, a_zx");
    h.value = RequiredFinite(held[i], "value", path, source);
    h.reason = OptionalString(held[i], "reason", path, source);
    out.push_back(std::move(h));
  }
  return out;
}

// The 1-sigma of the parameters: finite, except a held angle's (null: it was not fitted).
SensorModel ReadUncertainty(const json& unc, const std::vector<HeldMark>& held,
                            const std::string& source) {
  SensorModel u;
  u.bias_counts = ReadTriad(unc, "bias_counts", "uncertainty.", source);
  u.scale_counts_per_mps2 = ReadTriad(unc, "scale_counts_per_mps2", "uncertainty.", source);
  const json& mis = RequiredField(unc, "misalignment_rad", "uncertainty.", source);
  const auto angle = [&](const char* key, const char* name) {
    const bool is_held = std::any_of(held.begin(), held.end(), [&](const HeldMark& h) { return h.name == name; });
    return is_held ? OptionalFinite(mis, key, "uncertainty.misalignment_rad.", source)
                   : RequiredFinite(mis, key, "uncertainty.misalignment_rad.", source);
  };
  u.a_yz_rad = angle("yz", "a_yz");
  u.a_zy_rad = angle("zy", "a_zy");
  u.a_zx_rad = angle("zx", "a_zx");
  return u;
}

// What the readings were in; absent: counts.
ReadingUnit ReadReadingUnit(const json& j, const std::string& source) {
  ReadingUnit unit;
  if (!j.contains("reading_unit") || j.at("reading_unit").is_null()) return unit;
  const json& r = j.at("reading_unit");
  if (!r.is_object()) FailField(source, "reading_unit", "must be an object");
  const std::string name = OptionalString(r, "unit", "reading_unit.", source);
  const std::optional<ReadingUnit> parsed = StringToReadingUnit(name);
  if (!parsed) FailField(source, "reading_unit.unit", "must be \"counts\", \"m/s^2\" or \"g\"");
  unit = *parsed;
  if (!unit.is_counts()) unit.counts_per_unit = RequiredFinite(r, "counts_per_unit", "reading_unit.", source);
  if (std::string e = unit.Validate(); !e.empty()) FailField(source, "reading_unit", e);
  return unit;
}

GravitySpec ReadGravity(const json& j, const std::string& source) {
  const double g = RequiredFinite(j, "gravity_mps2", "", source);
  GravitySpec spec = GravitySpec::Given(g);
  if (!j.contains("gravity_source") || j["gravity_source"].is_null()) return spec;
  const json& gs = j["gravity_source"];
  if (!gs.is_object()) FailField(source, "gravity_source", "must be an object");
  const std::string kind = OptionalString(gs, "source", "gravity_source.", source, "given");
  if (kind == "standard") {
    spec.source = GravitySpec::Source::kStandard;
    spec.sigma_mps2 = kStandardGravitySigmaMps2;
  } else if (kind == "wgs84") {
    spec = GravitySpec::FromLocation(OptionalFinite(gs, "latitude_deg", "gravity_source.", source),
                                     OptionalFinite(gs, "altitude_m", "gravity_source.", source));
    spec.gravity_mps2 = g;  // as written (the formula may have changed since)
  } else if (kind != "given") {
    FailField(source, "gravity_source.source", "must be \"standard\", \"given\" or \"wgs84\"");
  }
  // Files written before the uncertainty was recorded lack it: the source's own then (a
  // measured value's stays "not stated").
  const double sigma = OptionalFinite(gs, "sigma_mps2", "gravity_source.", source);
  if (std::isfinite(sigma)) spec.sigma_mps2 = sigma;
  return spec;
}

CalibrationCapture ReadCapture(const json& c, size_t index, const std::string& source) {
  const std::string path = fmt::format("captures[{}].", index);
  if (!c.is_object()) FailField(source, fmt::format("captures[{}]", index), "must be an object");
  CalibrationCapture r;
  const json& id = RequiredField(c, "id", path, source);
  if (!id.is_number_integer()) FailField(source, path + "id", "must be an integer");
  r.id = id.get<int>();
  const json& kind = RequiredField(c, "kind", path, source);
  const auto k = kind.is_string() ? StringToCaptureKind(kind.get<std::string>()) : std::nullopt;
  if (!k) FailField(source, path + "kind", "must be \"static\" or \"turntable\"");
  r.kind = *k;
  r.label = OptionalString(c, "label", path, source);
  const json& used = RequiredField(c, "used", path, source);
  if (!used.is_boolean()) FailField(source, path + "used", "must be true or false");
  r.used = used.get<bool>();
  r.reason = OptionalString(c, "reason", path, source);
  r.n_samples = OptionalInteger(c, "n_samples", path, source, 0);
  r.residual_mps2 = OptionalFinite(c, "residual_mps2", path, source);
  r.reference_mps2 = OptionalFinite(c, "reference_mps2", path, source);
  r.sigma_mps2 = OptionalFinite(c, "sigma_mps2", path, source);
  r.radius_m = OptionalFinite(c, "radius_m", path, source);
  r.rpm = OptionalFinite(c, "rpm", path, source);
  r.t_start_s = OptionalFinite(c, "t_start_s", path, source);
  r.t_end_s = OptionalFinite(c, "t_end_s", path, source);
  r.mean_counts = OptionalTriad(c, "mean_counts", path, source);
  r.stage_residuals_mps2 = NumberArray(c, "stage_residuals_mps2", path, source, true);
  return r;
}

ScatterStructure ReadScatterStructure(const json& j, const std::string& path, const std::string& source) {
  ScatterStructure structure = ScatterStructure::kIndependent;
  if (!ScatterStructureFromString(OptionalString(j, "structure", path, source), &structure))
    FailField(source, path + "structure", "must be independent, flicker or random_walk");
  return structure;
}

ScatterModel ReadScatter(const json& j, const std::string& path, const std::string& source) {
  if (!j.is_object()) FailField(source, path.substr(0, path.size() - 1), "must be an object");
  ScatterModel m;
  m.structure = ReadScatterStructure(j, path, source);
  m.size = OptionalFinite(j, "size", path, source);
  m.min_dof = OptionalFinite(j, "min_dof", path, source);
  m.ratio_to_noise = OptionalFinite(j, "ratio_to_noise", path, source);
  if (j.contains("candidates") && !j["candidates"].is_null()) {
    const json& c = j["candidates"];
    if (!c.is_array()) FailField(source, path + "candidates", "must be an array");
    for (size_t i = 0; i < c.size(); ++i) {
      const std::string cp = fmt::format("{}candidates[{}].", path, i);
      if (!c[i].is_object()) FailField(source, cp.substr(0, cp.size() - 1), "must be an object");
      m.candidates.push_back({ReadScatterStructure(c[i], cp, source), OptionalFinite(c[i], "size", cp, source),
                              OptionalFinite(c[i], "log_likelihood", cp, source)});
    }
  }
  return m;
}

FitStatistics ReadFit(const json& f, const std::string& source, Calibration* cal) {
  FitStatistics s;
  if (f.is_null()) return s;
  if (!f.is_object()) FailField(source, "fit", "must be an object");
  const std::string p = "fit.";
  const std::string termination = OptionalString(f, "termination", p, source);
  s.termination = FitTermination::kNotRun;
  for (FitTermination t : {FitTermination::kConverged, FitTermination::kNoConvergence,
                           FitTermination::kNumericalFailure, FitTermination::kUnderdetermined,
                           FitTermination::kInvalidInput, FitTermination::kNotRun})
    if (FitTerminationToString(t) == termination) s.termination = t;
  s.captures_used = static_cast<int>(OptionalInteger(f, "captures_used", p, source, 0));
  s.dof = static_cast<int>(OptionalInteger(f, "dof", p, source, 0));
  s.chi2 = OptionalFinite(f, "chi2", p, source);
  s.chi2_per_dof = OptionalFinite(f, "chi2_per_dof", p, source);
  s.uncertainty_scale = OptionalFinite(f, "uncertainty_scale", p, source);
  s.condition_number = OptionalFinite(f, "condition_number", p, source);
  if (f.contains("most_correlated") && !f["most_correlated"].is_null()) {
    const json& m = f["most_correlated"];
    const std::string mp = p + "most_correlated.";
    s.most_correlated_first = OptionalString(m, "first", mp, source);
    s.most_correlated_second = OptionalString(m, "second", mp, source);
    s.most_correlated_rho = OptionalFinite(m, "rho", mp, source);
  }
  s.optimizer = OptionalString(f, "optimizer", p, source);
  if (f.contains("warnings") && !f["warnings"].is_null()) {
    const json& w = f["warnings"];
    if (!w.is_array()) FailField(source, p + "warnings", "must be an array of strings");
    for (size_t i = 0; i < w.size(); ++i) {
      if (!w[i].is_string()) FailField(source, fmt::format("{}warnings[{}]", p, i), "must be a string");
      s.warnings.push_back(w[i].get<std::string>());
    }
  }
  if (f.contains("diagnosis") && !f["diagnosis"].is_null()) {
    const json& d = f["diagnosis"];
    const std::string dp = p + "diagnosis.";
    DiagnosisOutcome o;
    o.ran = OptionalBool(d, "ran", dp, source, true);
    o.base_residual_rms_mps2 = OptionalFinite(d, "base_residual_rms_mps2", dp, source);
    o.noise_rms_mps2 = OptionalFinite(d, "noise_rms_mps2", dp, source);
    o.consistent_with_noise = OptionalBool(d, "consistent_with_noise", dp, source, false);
    o.conclusion = OptionalString(d, "conclusion", dp, source);
    cal->diagnosis = o;
  }
  if (f.contains("scatter") && !f["scatter"].is_null()) s.scatter = ReadScatter(f["scatter"], p + "scatter.", source);
  if (f.contains("stages") && !f["stages"].is_null()) {
    const json& st = f["stages"];
    if (!st.is_array()) FailField(source, p + "stages", "must be an array");
    for (size_t i = 0; i < st.size(); ++i) {
      const std::string sp = fmt::format("{}stages[{}].", p, i);
      cal->stages.push_back({OptionalString(st[i], "name", sp, source),
                             OptionalFinite(st[i], "rms_mps2", sp, source)});
    }
  }
  return s;
}

CalibrationEffect ReadEffect(const json& e, size_t index, const std::string& source,
                             EffectReference* reference) {
  const std::string path = fmt::format("effects[{}].", index);
  if (!e.is_object()) FailField(source, fmt::format("effects[{}]", index), "must be an object");
  CalibrationEffect r;
  const json& name = RequiredField(e, "name", path, source);
  if (!name.is_string()) FailField(source, path + "name", "must be a string");
  r.name = name.get<std::string>();
  const json& params = RequiredField(e, "parameters", path, source);
  if (!params.is_object()) FailField(source, path + "parameters", "must be an object name -> value");
  for (const auto& [key, value] : params.items()) {
    EffectParameter p;
    p.name = key;
    p.value = RequiredFinite(params, key, path + "parameters.", source);
    if (e.contains("uncertainty") && e["uncertainty"].is_object())
      p.sigma = OptionalFinite(e["uncertainty"], key, path + "uncertainty.", source);
    if (e.contains("units") && e["units"].is_object())
      p.unit = OptionalString(e["units"], key, path + "units.", source);
    r.parameters.push_back(p);
  }
  r.rms_before_mps2 = OptionalFinite(e, "rms_before_mps2", path, source);
  r.rms_after_mps2 = OptionalFinite(e, "rms_after_mps2", path, source);
  r.chi2_per_dof_before = OptionalFinite(e, "chi2_per_dof_before", path, source);
  r.chi2_per_dof_after = OptionalFinite(e, "chi2_per_dof_after", path, source);
  r.corrects_readings = OptionalBool(e, "corrects_readings", path, source, false);
  r.evidence = OptionalString(e, "evidence", path, source);
  if (e.contains("reference") && e["reference"].is_object()) {
    const double temp_c = OptionalFinite(e["reference"], "temp_c", path + "reference.", source);
    const double t_s = OptionalFinite(e["reference"], "t_s", path + "reference.", source);
    if (std::isfinite(temp_c)) reference->temp_c = temp_c;
    if (std::isfinite(t_s)) reference->t_s = t_s;
  }
  return r;
}

}  // namespace

Calibration CalibrationFromJson(const json& j, const std::string& source) {
  if (!j.is_object()) throw InputError(source, 0, 0, "not a JSON object");
  const json& format = RequiredField(j, "format", "", source);
  if (!format.is_string() || format.get<std::string>() != kCalibrationFormat)
    FailField(source, "format", fmt::format("is {}, expected \"{}\"", format.dump(), kCalibrationFormat));
  Calibration cal;
  cal.model = ReadModel(j, "", source);
  if (std::string e = cal.model.Validate(); !e.empty()) throw InputError(source, 0, 0, e);
  const json& unc = RequiredField(j, "uncertainty", "", source);
  cal.held = ReadHeld(j, source);
  cal.uncertainty = ReadUncertainty(unc, cal.held, source);
  cal.reading_unit = ReadReadingUnit(j, source);
  cal.gravity = ReadGravity(j, source);
  cal.residual_rms_mps2 = OptionalFinite(j, "residual_rms_mps2", "", source);
  cal.residual_max_abs_mps2 = OptionalFinite(j, "residual_max_abs_mps2", "", source);
  cal.source = OptionalString(j, "source", "", source);
  cal.fit = ReadFit(j.contains("fit") ? j["fit"] : json(nullptr), source, &cal);
  const json& effects = RequiredField(j, "effects", "", source);
  if (!effects.is_array()) FailField(source, "effects", "must be an array");
  for (size_t i = 0; i < effects.size(); ++i)
    cal.effects.push_back(ReadEffect(effects[i], i, source, &cal.reference));
  const json& captures = RequiredField(j, "captures", "", source);
  if (!captures.is_array()) FailField(source, "captures", "must be an array");
  for (size_t i = 0; i < captures.size(); ++i) cal.captures.push_back(ReadCapture(captures[i], i, source));
  if (j.contains("uncertainty_budget") && !j.at("uncertainty_budget").is_null())
    cal.budget = detail::BudgetFromJson(j.at("uncertainty_budget"), source);
  if (j.contains("limited_by") && !j.at("limited_by").is_null()) {
    const json& l = j.at("limited_by");
    if (!l.is_array()) FailField(source, "limited_by", "must be an array");
    for (size_t i = 0; i < l.size(); ++i) {
      const std::string lp = fmt::format("limited_by[{}].", i);
      if (!l[i].is_object()) FailField(source, fmt::format("limited_by[{}]", i), "must be an object");
      cal.limited_by.push_back({OptionalString(l[i], "kind", lp, source), OptionalString(l[i], "words", lp, source)});
    }
  }
  return cal;
}

json CalibrationToJson(const Calibration& cal) {
  json captures = json::array();
  for (const CalibrationCapture& c : cal.captures) captures.push_back(CaptureJson(c));
  json effects = json::array();
  for (const CalibrationEffect& e : cal.effects) effects.push_back(EffectJson(e, cal.reference));
  json held = json::array();
  for (const HeldMark& h : cal.held) held.push_back({{"name", h.name}, {"value", h.value}, {"reason", h.reason}});
  json unit = {{"unit", cal.reading_unit.Name()}, {"description", cal.reading_unit.Describe()}};
  if (!cal.reading_unit.is_counts()) unit["counts_per_unit"] = cal.reading_unit.counts_per_unit;
  json out = {{"format", kCalibrationFormat},
          {"tool", std::string("accelcal ") + kAccelcalVersion},
          {"source", cal.source},
          {"gravity_mps2", cal.gravity.gravity_mps2},
          {"gravity_source", GravityJson(cal.gravity)},
          {"bias_counts", JsonTriad(cal.model.bias_counts)},
          {"scale_counts_per_mps2", JsonTriad(cal.model.scale_counts_per_mps2)},
          {"misalignment_rad", Misalignment(cal.model)},
          {"uncertainty",
           {{"bias_counts", JsonTriad(cal.uncertainty.bias_counts)},
            {"scale_counts_per_mps2", JsonTriad(cal.uncertainty.scale_counts_per_mps2)},
            {"misalignment_rad", Misalignment(cal.uncertainty)}}},
          {"held", held},
          {"reading_unit", unit},
          {"residual_rms_mps2", JsonNumber(cal.residual_rms_mps2)},
          {"residual_max_abs_mps2", JsonNumber(cal.residual_max_abs_mps2)},
          {"fit", FitJson(cal)},
          {"effects", effects},
          {"captures", captures}};
  if (cal.budget) out["uncertainty_budget"] = detail::BudgetToJson(*cal.budget);
  if (!cal.limited_by.empty()) {
    json limits = json::array();
    for (const UncertaintyLimit& l : cal.limited_by) limits.push_back({{"kind", l.kind}, {"words", l.words}});
    out["limited_by"] = limits;
  }
  return out;
}

std::string CalibrationToJsonText(const Calibration& cal) { return detail::JsonText(CalibrationToJson(cal)); }

Calibration CalibrationFromJsonText(const std::string& text, const std::string& source_name) {
  return CalibrationFromJson(ParseJsonText(text, source_name), source_name);
}

void WriteCalibrationFile(const std::string& path, const Calibration& cal) {
  // Beside and renamed, so a crash never leaves a half-written calibration behind.
  WriteFileAtomically(path, CalibrationToJsonText(cal) + "\n");
}

Calibration ReadCalibrationFile(const std::string& path) {
  return CalibrationFromJsonText(detail::ReadWholeFile(path), path);
}

}  // namespace accelcal
