#include "accelcal/io/calibration_file.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/core.h>

#include "accelcal/io/atomic_write.h"
#include "accelcal/base/error.h"

namespace accelcal {
namespace {

using nlohmann::json;

// NaN is not JSON: absent values are written as null.
json Number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json Triad(const Eigen::Vector3d& v) { return json::array({Number(v.x()), Number(v.y()), Number(v.z())}); }

json Misalignment(const SensorModel& m) {
  return {{"yz", Number(m.a_yz_rad)}, {"zy", Number(m.a_zy_rad)}, {"zx", Number(m.a_zx_rad)}};
}

json GravityJson(const GravitySpec& g) {
  json j = {{"source", g.SourceName()}, {"description", g.Describe()}};
  if (g.source == GravitySpec::Source::kWgs84) {
    j["latitude_deg"] = g.latitude_deg;
    j["altitude_m"] = g.altitude_m;
  }
  return j;
}

json CaptureJson(const CaptureRecord& c) {
  return {{"id", c.id},
          {"kind", std::string(CaptureKindToString(c.kind))},
          {"label", c.label},
          {"used", c.used},
          {"reason", c.used ? json(nullptr) : json(c.reason)},
          {"n_samples", c.n_samples},
          {"residual_mps2", Number(c.residual_mps2)},
          {"reference_mps2", Number(c.reference_mps2)},
          {"sigma_mps2", Number(c.sigma_mps2)},
          {"radius_m", Number(c.radius_m)},
          {"rpm", Number(c.rpm)},
          {"t_start_s", Number(c.t_start_s)},
          {"t_end_s", Number(c.t_end_s)},
          {"mean_counts", Triad(c.mean_counts)}};
}

json FitJson(const FitSummary& s) {
  json warnings = json::array();
  for (const std::string& w : s.warnings) warnings.push_back(w);
  json correlated = nullptr;
  if (s.most_correlated.first >= 0)
    correlated = {{"first", s.parameter_labels[s.most_correlated.first]},
                  {"second", s.parameter_labels[s.most_correlated.second]},
                  {"rho", s.most_correlated.rho}};
  return {{"termination", std::string(FitTerminationToString(s.termination))},
          {"captures_used", s.num_captures},
          {"dof", s.dof},
          {"chi2", s.chi2},
          {"chi2_per_dof", s.dof > 0 ? json(s.Chi2PerDof()) : json(nullptr)},
          {"uncertainty_scale", s.uncertainty_scale},
          {"condition_number", s.condition_number},
          {"most_correlated", correlated},
          {"optimizer", fmt::format("NLopt SLSQP ({}, {} evaluations) + Gauss-Newton ({} iterations)",
                                    s.optimizer_result, s.optimizer_evaluations,
                                    s.gauss_newton_iterations)},
          {"warnings", warnings}};
}

// --- strict reading -------------------------------------------------------------------------

[[noreturn]] void Fail(const std::string& source, const std::string& field, const std::string& what) {
  throw InputError(source, 0, 0, fmt::format("field '{}': {}", field, what));
}

const json& Field(const json& j, const std::string& key, const std::string& path, const std::string& source) {
  if (!j.is_object() || !j.contains(key)) Fail(source, path + key, "missing");
  return j.at(key);
}

double FiniteNumber(const json& j, const std::string& key, const std::string& path, const std::string& source) {
  const json& v = Field(j, key, path, source);
  if (!v.is_number()) Fail(source, path + key, "must be a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) Fail(source, path + key, "must be finite");
  return d;
}

double OptionalNumber(const json& j, const std::string& key) {
  return (j.contains(key) && j.at(key).is_number()) ? j.at(key).get<double>() : kNaN;
}

Eigen::Vector3d ReadTriad(const json& j, const std::string& key, const std::string& path, const std::string& source) {
  const json& v = Field(j, key, path, source);
  if (!v.is_array() || v.size() != 3) Fail(source, path + key, "must be an array of 3 numbers");
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) {
    if (!v[i].is_number() || !std::isfinite(v[i].get<double>()))
      Fail(source, fmt::format("{}{}[{}]", path, key, i), "must be a finite number");
    out(i) = v[i].get<double>();
  }
  return out;
}

SensorModel ReadModel(const json& j, const std::string& path, const std::string& source) {
  SensorModel m;
  m.bias_counts = ReadTriad(j, "bias_counts", path, source);
  m.scale_counts_per_mps2 = ReadTriad(j, "scale_counts_per_mps2", path, source);
  const json& mis = Field(j, "misalignment_rad", path, source);
  m.a_yz_rad = FiniteNumber(mis, "yz", path + "misalignment_rad.", source);
  m.a_zy_rad = FiniteNumber(mis, "zy", path + "misalignment_rad.", source);
  m.a_zx_rad = FiniteNumber(mis, "zx", path + "misalignment_rad.", source);
  return m;
}

GravitySpec ReadGravity(const json& j, const std::string& source) {
  const double g = FiniteNumber(j, "gravity_mps2", "", source);
  GravitySpec spec = GravitySpec::Given(g);
  if (j.contains("gravity_source") && j["gravity_source"].is_object()) {
    const json& gs = j["gravity_source"];
    const std::string kind = gs.value("source", "given");
    if (kind == "standard") spec.source = GravitySpec::Source::kStandard;
    if (kind == "wgs84") {
      spec.source = GravitySpec::Source::kWgs84;
      spec.latitude_deg = OptionalNumber(gs, "latitude_deg");
      spec.altitude_m = OptionalNumber(gs, "altitude_m");
    }
  }
  return spec;
}

CaptureRecord ReadCapture(const json& c, size_t index, const std::string& source) {
  const std::string path = fmt::format("captures[{}].", index);
  CaptureRecord r;
  const json& id = Field(c, "id", path, source);
  if (!id.is_number_integer()) Fail(source, path + "id", "must be an integer");
  r.id = id.get<int>();
  const json& kind = Field(c, "kind", path, source);
  const auto k = kind.is_string() ? StringToCaptureKind(kind.get<std::string>()) : std::nullopt;
  if (!k) Fail(source, path + "kind", "must be \"static\" or \"turntable\"");
  r.kind = *k;
  r.label = c.value("label", "");
  const json& used = Field(c, "used", path, source);
  if (!used.is_boolean()) Fail(source, path + "used", "must be true or false");
  r.used = used.get<bool>();
  if (c.contains("reason") && c["reason"].is_string()) r.reason = c["reason"].get<std::string>();
  r.n_samples = c.value("n_samples", 0L);
  r.residual_mps2 = OptionalNumber(c, "residual_mps2");
  r.reference_mps2 = OptionalNumber(c, "reference_mps2");
  r.sigma_mps2 = OptionalNumber(c, "sigma_mps2");
  r.radius_m = OptionalNumber(c, "radius_m");
  r.rpm = OptionalNumber(c, "rpm");
  r.t_start_s = OptionalNumber(c, "t_start_s");
  r.t_end_s = OptionalNumber(c, "t_end_s");
  if (c.contains("mean_counts") && c["mean_counts"].is_array() && c["mean_counts"].size() == 3)
    for (int i = 0; i < 3; ++i) r.mean_counts(i) = c["mean_counts"][i].is_number() ? c["mean_counts"][i].get<double>() : kNaN;
  return r;
}

}  // namespace

std::vector<CaptureRecord> MakeCaptureRecords(const std::vector<Capture>& all,
                                              const FitSummary& summary) {
  std::vector<CaptureRecord> records;
  for (const Capture& c : all) {
    const CaptureStats stats = ComputeStats(c.samples);
    CaptureRecord r;
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
    for (const CaptureResidual& res : summary.residuals) {
      if (res.id == c.id && r.used && summary.IsUsable()) {
        r.residual_mps2 = res.residual_mps2;
        r.reference_mps2 = res.reference_mps2;
        r.sigma_mps2 = res.sigma_mps2;
      }
    }
    records.push_back(r);
  }
  return records;
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
  cal.fit = FitJson(summary);
  cal.captures = MakeCaptureRecords(all, summary);
  return cal;
}

json CalibrationToJson(const Calibration& cal) {
  json captures = json::array();
  for (const CaptureRecord& c : cal.captures) captures.push_back(CaptureJson(c));
  return {{"format", kCalibrationFormat},
          {"tool", std::string("accelcal ") + ACCELCAL_VERSION},
          {"source", cal.source},
          {"gravity_mps2", cal.gravity.gravity_mps2},
          {"gravity_source", GravityJson(cal.gravity)},
          {"bias_counts", Triad(cal.model.bias_counts)},
          {"scale_counts_per_mps2", Triad(cal.model.scale_counts_per_mps2)},
          {"misalignment_rad", Misalignment(cal.model)},
          {"uncertainty",
           {{"bias_counts", Triad(cal.uncertainty.bias_counts)},
            {"scale_counts_per_mps2", Triad(cal.uncertainty.scale_counts_per_mps2)},
            {"misalignment_rad", Misalignment(cal.uncertainty)}}},
          {"residual_rms_mps2", Number(cal.residual_rms_mps2)},
          {"residual_max_abs_mps2", Number(cal.residual_max_abs_mps2)},
          {"fit", cal.fit},
          {"effects", cal.effects},
          {"captures", captures}};
}

Calibration CalibrationFromJson(const json& j, const std::string& source) {
  if (!j.is_object()) throw InputError(source, 0, 0, "not a JSON object");
  const json& format = Field(j, "format", "", source);
  if (!format.is_string() || format.get<std::string>() != kCalibrationFormat)
    Fail(source, "format", fmt::format("is {}, expected \"{}\"", format.dump(), kCalibrationFormat));
  Calibration cal;
  cal.model = ReadModel(j, "", source);
  if (std::string e = cal.model.Validate(); !e.empty()) throw InputError(source, 0, 0, e);
  const json& unc = Field(j, "uncertainty", "", source);
  cal.uncertainty = ReadModel(unc, "uncertainty.", source);
  cal.gravity = ReadGravity(j, source);
  cal.residual_rms_mps2 = OptionalNumber(j, "residual_rms_mps2");
  cal.residual_max_abs_mps2 = OptionalNumber(j, "residual_max_abs_mps2");
  cal.source = j.value("source", "");
  if (j.contains("fit")) cal.fit = j["fit"];
  const json& effects = Field(j, "effects", "", source);
  if (!effects.is_array()) Fail(source, "effects", "must be an array");
  cal.effects = effects;
  const json& captures = Field(j, "captures", "", source);
  if (!captures.is_array()) Fail(source, "captures", "must be an array");
  for (size_t i = 0; i < captures.size(); ++i) cal.captures.push_back(ReadCapture(captures[i], i, source));
  return cal;
}

void WriteCalibrationFile(const std::string& path, const Calibration& cal) {
  // Beside and renamed, so a crash never leaves a half-written calibration behind.
  WriteFileAtomically(path, CalibrationToJson(cal).dump(2) + "\n");
}

Calibration ReadCalibrationFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(fmt::format("cannot open '{}': {}", path, std::strerror(errno)));
  std::stringstream text;
  text << in.rdbuf();
  json j;
  try {
    j = json::parse(text.str());
  } catch (const json::parse_error& e) {
    // nlohmann reports a byte offset; turn it into line and column.
    const std::string s = text.str();
    const size_t at = std::min<size_t>(e.byte == 0 ? 0 : e.byte - 1, s.size());
    long line = 1, col = 1;
    for (size_t i = 0; i < at; ++i) {
      if (s[i] == '\n') { ++line; col = 1; } else { ++col; }
    }
    throw InputError(path, line, col, "not valid JSON");
  }
  return CalibrationFromJson(j, path);
}

}  // namespace accelcal
