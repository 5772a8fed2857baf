#include "accelcal/io/allan_file.h"

#include <cmath>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/io/atomic_write.h"
#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/detail/json_values.h"
#include "accelcal/io/detail/read_file.h"

namespace accelcal {
namespace {

using namespace detail;  // the JSON helpers

json Conventions() {
  return {
      {"standard", "IEEE Std 952-1997 Annex C (IEEE Std 1293-2018 for accelerometers)"},
      {"allan", "overlapping Allan deviation of the axis readings; bounds at 68.3 % from "
                "Greenhall-Riley equivalent degrees of freedom with lag-1/B1 noise "
                "identification (Stable32's method)"},
      {"noise_density", "slope -1/2 line sigma = N/sqrt(tau) read at tau = 1 s; unit/sqrt(Hz); "
                        "from an edf-weighted fit of sigma^2 = N^2/tau + C + K^2 tau/3"},
      {"bias_instability", "minimum of the curve divided by 0.664; unit"},
      {"random_walk", "slope +1/2 line sigma = K sqrt(tau/3) read at tau = 3 s; unit/sqrt(s)"},
      {"max_drift", "peak to peak of the means over consecutive drift windows; unit"}};
}

json AxisToJson(const AxisAnalysis& axis, double drift_window_s) {
  json a;
  const bool have = axis.read_offs.has_value();
  a["noise_density"] = have ? JsonNumber(axis.read_offs->noise_density) : json(nullptr);
  a["bias_instability"] = have ? JsonNumber(axis.read_offs->bias_instability) : json(nullptr);
  a["bias_instability_tau_s"] = have ? JsonNumber(axis.read_offs->bias_instability_tau_s) : json(nullptr);
  a["random_walk"] = have ? JsonNumber(axis.read_offs->random_walk) : json(nullptr);
  a["white_noise_observed"] = have && axis.read_offs->white_noise_observed;
  a["random_walk_observed"] = have && axis.read_offs->random_walk_observed;
  a["max_drift"] = JsonNumber(axis.drift.max_drift);
  a["drift_window_s"] = drift_window_s;
  a["drift_windows"] = axis.drift.windows;
  a["temperature_correlation"] = JsonNumber(axis.drift.temp_correlation);
  a["temperature_slope_per_c"] = JsonNumber(axis.drift.temp_slope_per_c);
  json notes = json::array();
  if (have)
    for (const std::string& n : axis.read_offs->notes) notes.push_back(n);
  else
    notes.push_back("too short for read-offs: fewer than 3 averaging times");
  a["notes"] = notes;
  json tau = json::array(), adev = json::array(), lo = json::array(), hi = json::array(),
       edf = json::array(), terms = json::array(), alpha = json::array();
  for (const AllanPoint& p : axis.curve.points) {
    tau.push_back(p.tau_s);
    adev.push_back(JsonNumber(p.adev));
    lo.push_back(JsonNumber(p.adev_lo));
    hi.push_back(JsonNumber(p.adev_hi));
    edf.push_back(JsonNumber(p.edf));
    terms.push_back(p.num_terms);
    alpha.push_back(p.alpha);
  }
  a["tau_s"] = tau;
  a["adev"] = adev;
  a["adev_lo"] = lo;
  a["adev_hi"] = hi;
  a["edf"] = edf;
  a["num_terms"] = terms;
  a["alpha"] = alpha;
  return a;
}

constexpr const char* kAxisNames[3] = {"x", "y", "z"};

std::string ReadUnit(const json& j, const std::string& source) {
  if (!j.is_object()) throw InputError(source, 0, 0, "not a JSON object");
  if (!j.contains("unit") || !j["unit"].is_string()) FailField(source, "unit", "missing (\"counts\" or \"m/s^2\")");
  const std::string unit = j["unit"].get<std::string>();
  if (unit != "counts" && unit != "m/s^2") FailField(source, "unit", "is \"" + unit + "\", expected \"counts\" or \"m/s^2\"");
  return unit;
}

const json& ReadAxes(const json& j, const std::string& source) {
  if (!j.contains("axes") || !j["axes"].is_object()) FailField(source, "axes", "missing (an object with x, y, z)");
  const json& axes = j["axes"];
  for (const auto& [key, value] : axes.items())
    if (key != "x" && key != "y" && key != "z") FailField(source, "axes." + key, "unknown axis (x, y or z)");
  if (axes.empty()) FailField(source, "axes", "has no axis");
  return axes;
}

// Calls fn(index, axis object, "axes.x.") for each of x, y, z present in `axes`; an axis that is
// not an object is refused.
template <typename Fn>
void ForEachAxis(const json& axes, const std::string& source, Fn&& fn) {
  for (int i = 0; i < 3; ++i) {
    if (!axes.contains(kAxisNames[i])) continue;
    const json& x = axes[kAxisNames[i]];
    const std::string path = fmt::format("axes.{}.", kAxisNames[i]);
    if (!x.is_object()) FailField(source, path, "must be an object");
    fn(i, x, path);
  }
}

// `accelcal noise -o FILE` (format "accelcal-noise/1"): the first record's std and density,
// and the bias repeatability (std of the records' means) when there are several records.
NoiseSection ParseNoiseReportJson(const json& j, const std::string& source) {
  NoiseSection n;
  n.unit = ReadUnit(j, source);
  const json& records = j["records"];
  if (!records.is_array() || records.empty() || !records[0].is_object())
    FailField(source, "records", "must be a non-empty array of records");
  n.source = records.size() > 1 ? fmt::format("{}, record 1 of {}", source, records.size()) : source;
  const json& axes = ReadAxes(records[0], source);
  std::vector<double> repeat;
  if (j.contains("repeatability") && j["repeatability"].is_object())
    repeat = NumberArray(j["repeatability"], "std_of_means", "repeatability.", source, true);
  for (int i = 0; i < 3; ++i) {
    if (!axes.contains(kAxisNames[i])) continue;
    const std::string path = fmt::format("records[0].axes.{}.", kAxisNames[i]);
    const json& x = axes[kAxisNames[i]];
    if (!x.is_object()) FailField(source, path, "must be an object");
    NoiseAxis ax;
    ax.std = OptionalFinite(x, "std", path, source);
    ax.noise_density = OptionalFinite(x, "density", path, source);
    if (repeat.size() == 3) ax.bias_repeatability = repeat[static_cast<size_t>(i)];
    n.axes[i] = ax;
  }
  return n;
}

}  // namespace

nlohmann::json RecordAnalysisToJson(const RecordAnalysis& r, const std::string& source,
                                    double drift_window_s) {
  json j;
  j["format"] = "accelcal-allan";
  j["version"] = 1;
  j["source"] = source;
  j["unit"] = r.unit;
  j["rate_hz"] = JsonNumber(r.rate_hz);
  j["rate_estimated"] = r.rate_estimated;
  j["samples"] = r.samples;
  j["missing_samples"] = r.missing_samples;
  j["duration_s"] = JsonNumber(r.t_last_s - r.t_first_s);
  json gaps = json::array();
  for (const RecordAnalysisGap& g : r.gaps)
    gaps.push_back({{"t_before_s", g.t_before_s}, {"t_after_s", g.t_after_s},
                    {"missing_samples", g.missing_samples}});
  j["gaps"] = gaps;
  double tmin = kNaN, tmax = kNaN;
  for (const AxisAnalysis& a : r.axes) {
    if (!std::isnan(a.drift.temp_min_c)) tmin = std::isnan(tmin) ? a.drift.temp_min_c : std::min(tmin, a.drift.temp_min_c);
    if (!std::isnan(a.drift.temp_max_c)) tmax = std::isnan(tmax) ? a.drift.temp_max_c : std::max(tmax, a.drift.temp_max_c);
  }
  j["temperature_c"] = std::isnan(tmin) ? json(nullptr) : json{{"min", tmin}, {"max", tmax}};
  j["conventions"] = Conventions();
  j["axes"] = {{"x", AxisToJson(r.axes[0], drift_window_s)},
               {"y", AxisToJson(r.axes[1], drift_window_s)},
               {"z", AxisToJson(r.axes[2], drift_window_s)}};
  return j;
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
    if (ax.adev.size() != ax.tau_s.size()) FailField(source, path + "adev", "must have as many values as tau_s");
    if (!ax.adev_lo.empty() && ax.adev_lo.size() != ax.tau_s.size())
      FailField(source, path + "adev_lo", "must have as many values as tau_s");
    if (!ax.adev_hi.empty() && ax.adev_hi.size() != ax.tau_s.size())
      FailField(source, path + "adev_hi", "must have as many values as tau_s");
    for (size_t k = 0; k < ax.tau_s.size(); ++k)
      if (ax.tau_s[k] <= 0.0 || ax.adev[k] <= 0.0)  // false for a NaN (null) adev
        FailField(source, fmt::format("{}tau_s[{}]", path, k), "tau and adev must be positive (log axes)");
    a.axes[i] = ax;
  });
  return a;
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
    axes[kAxisNames[i]] = {{"noise_density", JsonNumber(x.noise_density)},
                           {"bias_instability", JsonNumber(x.bias_instability)},
                           {"random_walk", JsonNumber(x.random_walk)},
                           {"max_drift", JsonNumber(x.max_drift)},
                           {"tau_s", x.tau_s},
                           {"adev", x.adev},
                           {"adev_lo", x.adev_lo},
                           {"adev_hi", x.adev_hi}};
  }
  return {{"unit", a.unit}, {"rate_hz", JsonNumber(a.rate_hz)}, {"axes", axes}, {"source", a.source}};
}

json NoiseToJson(const NoiseSection& n) {
  json axes = json::object();
  for (int i = 0; i < 3; ++i) {
    if (!n.axes[i]) continue;
    const NoiseAxis& x = *n.axes[i];
    axes[kAxisNames[i]] = {{"std", JsonNumber(x.std)}, {"noise_density", JsonNumber(x.noise_density)},
                           {"bias_repeatability", JsonNumber(x.bias_repeatability)}};
  }
  return {{"unit", n.unit}, {"axes", axes}, {"source", n.source}};
}

void ReadAnalysesFromResult(const json& result, const std::string& source, ReportInputs* inputs) {
  if (!result.is_object()) return;
  if (result.contains("allan") && !result["allan"].is_null())
    inputs->allan = ParseAllanJson(result["allan"], source + " (result key allan)");
  if (result.contains("noise") && !result["noise"].is_null())
    inputs->noise = ParseNoiseJson(result["noise"], source + " (result key noise)");
  if (result.contains("session_gaps") && !result["session_gaps"].is_null())
    inputs->gaps = SessionGapsFromJson(result["session_gaps"], source);
}

std::string AllanFileText(const RecordAnalysis& analysis, const std::string& source,
                          double drift_window_s) {
  return detail::JsonText(RecordAnalysisToJson(analysis, source, drift_window_s)) + "\n";
}

void WriteAllanFile(const std::string& path, const std::string& text) { WriteFileAtomically(path, text); }

AllanSection ParseAllanText(const std::string& text, const std::string& source) {
  return ParseAllanJson(ParseJsonText(text, source), source);
}

AllanSection ReadAllanFile(const std::string& path) { return ParseAllanText(ReadWholeFile(path), path); }

}  // namespace accelcal
