#include "accelcal/io/allan_file.h"

#include <cmath>

#include "accelcal/io/atomic_write.h"

namespace accelcal {
namespace {

using nlohmann::json;

// JSON has no NaN: a figure that is not known is null.
json Number(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

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
  a["noise_density"] = have ? Number(axis.read_offs->noise_density) : json(nullptr);
  a["bias_instability"] = have ? Number(axis.read_offs->bias_instability) : json(nullptr);
  a["bias_instability_tau_s"] = have ? Number(axis.read_offs->bias_instability_tau_s) : json(nullptr);
  a["random_walk"] = have ? Number(axis.read_offs->random_walk) : json(nullptr);
  a["white_noise_observed"] = have && axis.read_offs->white_noise_observed;
  a["random_walk_observed"] = have && axis.read_offs->random_walk_observed;
  a["max_drift"] = Number(axis.drift.max_drift);
  a["drift_window_s"] = drift_window_s;
  a["drift_windows"] = axis.drift.windows;
  a["temperature_correlation"] = Number(axis.drift.temp_correlation);
  a["temperature_slope_per_c"] = Number(axis.drift.temp_slope_per_c);
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
    adev.push_back(Number(p.adev));
    lo.push_back(Number(p.adev_lo));
    hi.push_back(Number(p.adev_hi));
    edf.push_back(Number(p.edf));
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

}  // namespace

nlohmann::json RecordAnalysisToJson(const RecordAnalysis& r, const std::string& source,
                                    double drift_window_s) {
  json j;
  j["format"] = "accelcal-allan";
  j["version"] = 1;
  j["source"] = source;
  j["unit"] = r.unit;
  j["rate_hz"] = Number(r.rate_hz);
  j["rate_estimated"] = r.rate_estimated;
  j["samples"] = r.samples;
  j["missing_samples"] = r.missing_samples;
  j["duration_s"] = Number(r.t_last_s - r.t_first_s);
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

void WriteAllanFile(const std::string& path, const nlohmann::json& allan) {
  WriteFileAtomically(path, allan.dump(2) + "\n");
}

}  // namespace accelcal
