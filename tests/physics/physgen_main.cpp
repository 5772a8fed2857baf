// accelcal_physgen: the independent physics bench (physics_bench.h) as a command.
//
//   accelcal_physgen generate [--plan seed|rich] [--case NAME] [--seed N] [options]
//                             -o SET.csv --truth TRUTH.json
//   accelcal_physgen compare TRUTH.json CAL.json      one tab-separated line (evaluate.sh)
//   accelcal_physgen tally RESULTS.tsv                the tables of evaluate.sh
//   accelcal_physgen selfcheck                        the generator against the physics
//   accelcal_physgen cases                            the named cases
//   accelcal_physgen means SET.csv CAL.json           mean readings for `accelcal apply`
//   accelcal_physgen residuals SET.csv CAL.json APPLIED.txt   apply_check.cpp
//
// --no-temperature leaves the temp_c column empty (the sensor still warms: a temperature effect
// injected then acts unobserved). The generator uses only the standard library and Eigen; `compare` reads accelcal's
// calibration file with nlohmann-json. Nothing of the project is included.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "physics_bench.h"

namespace physgen {
int MeansCommand(const std::vector<std::string>& args);      // apply_check.cpp
int ResidualsCommand(const std::vector<std::string>& args);  // apply_check.cpp
}  // namespace physgen

namespace {

using physgen::Bench;
using physgen::CaptureSpec;
using physgen::Effects;
using physgen::Sensor;

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void Usage(const std::string& why) {
  std::cerr << "accelcal_physgen: " << why << "\n"
            << "usage: accelcal_physgen generate [--plan seed|rich] [--case NAME] [--seed N]\n"
               "         [--gravity G] [--static-s S] [--turntable-s S] [--rate HZ] [--noise N|X,Y,Z]\n"
               "         [--placement-deg D] [--gap MIN,MAX] [--temperature START,END] [--warmup-tau S]\n"
               "         [--no-temperature] [--no-quantize]\n"
               "         [--fixed-sensor] [--quadratic X,Y,Z] [--temp-bias X,Y,Z] [--temp-scale X,Y,Z]\n"
               "         [--drift X,Y,Z] [--radius-offset M] [--rpm-scale S] [--size X,Y,Z]\n"
               "         [--cubic X,Y,Z] [--cross C] [--tilt-deg D] [--asym X,Y,Z] [--bias-jump X,Y,Z]\n"
               "         [--turntable-bias X,Y,Z] [--bias-walk X,Y,Z] [--flicker X,Y,Z]\n"
               "         [--settle X,Y,Z] [--settle-tau S] [--settle-lead S] -o SET.csv [--truth TRUTH.json]\n"
               "       accelcal_physgen compare TRUTH.json CAL.json\n"
               "       accelcal_physgen tally RESULTS.tsv\n"
               "       accelcal_physgen selfcheck\n"
               "       accelcal_physgen cases\n"
               "       accelcal_physgen means SET.csv CAL.json\n"
               "       accelcal_physgen residuals SET.csv CAL.json APPLIED.txt\n";
  std::exit(2);
}

double ParseNumber(const std::string& s) {
  size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(s, &used);
  } catch (...) {
    Usage("not a number: '" + s + "'");
  }
  if (used != s.size()) Usage("not a number: '" + s + "'");
  return v;
}

Eigen::Vector3d ParseVector(const std::string& s) {
  std::vector<double> v;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) v.push_back(ParseNumber(item));
  if (v.size() == 1) return Eigen::Vector3d::Constant(v[0]);
  if (v.size() != 3) Usage("expected X,Y,Z or one value: '" + s + "'");
  return {v[0], v[1], v[2]};
}

// --- the named cases: each effect alone at a realistic size ----------------------------------
struct Case {
  const char* name;
  const char* what;
  void (*apply)(Effects&);
};

const std::vector<Case>& Cases() {
  static const std::vector<Case> cases = {
      {"clean", "the nine-parameter model exactly", [](Effects&) {}},
      {"quadratic", "in library: q = (0.02, -0.015, 0.01) counts/(m/s^2)^2",
       [](Effects& e) { e.quadratic = {0.02, -0.015, 0.01}; }},
      {"temperature_bias", "in library: tc_bias = (0.5, -0.3, 0.8) counts/degC",
       [](Effects& e) { e.temp_bias = {0.5, -0.3, 0.8}; }},
      {"temperature_scale", "in library: tc_scale = (2e-4, 2e-4, -1e-4) 1/degC",
       [](Effects& e) { e.temp_scale = {2e-4, 2e-4, -1e-4}; }},
      {"bias_drift", "in library: drift = (0.002, 0, -0.001) counts/s",
       [](Effects& e) { e.drift = {0.002, 0.0, -0.001}; }},
      {"radius_offset", "in library: dr = 3 mm", [](Effects& e) { e.radius_offset_m = 0.003; }},
      {"rpm_scale", "in library: true speed 1 % above the stated", [](Effects& e) { e.rpm_scale = 0.01; }},
      {"size_effect", "in library: d = (1.5, -1.0, 2.0) mm",
       [](Effects& e) { e.size_effect_m = {0.0015, -0.001, 0.002}; }},
      {"cubic", "in library since issue 13: raw_x += 1e-4 u_x^3 counts (u in m/s^2; 38 mm/s^2 at 2.4 g)",
       [](Effects& e) { e.cubic = {1e-4, 0.0, 0.0}; }},
      {"cross", "in library since issue 13: raw_x += 0.03 u_y u_z counts (28 mm/s^2 at the (1,1,1) corner)",
       [](Effects& e) { e.cross_x_yz = 0.03; }},
      {"tilt", "in library since issue 13: turntable spin axis tilted 2 deg",
       [](Effects& e) { e.tilt_rad = 2.0 * kPi / 180.0; }},
      {"radius_size", "two in library: dr = 3 mm and d = (1.5, -1.0, 2.0) mm",
       [](Effects& e) { e.radius_offset_m = 0.003; e.size_effect_m = {0.0015, -0.001, 0.002}; }},
      {"quadratic_temperature", "two in library: q = (0.02, -0.015, 0.01), tc_bias = (0.5, -0.3, 0.8)",
       [](Effects& e) { e.quadratic = {0.02, -0.015, 0.01}; e.temp_bias = {0.5, -0.3, 0.8}; }},
      {"asym_scale", "outside: the x sensitivity is 0.3 % above its mean for positive inputs, 0.3 % below for negative",
       [](Effects& e) { e.asym_scale = {0.003, 0.0, 0.0}; }},
      {"bias_jump", "outside: the zero-g level steps by (2, 0, -1.5) counts once, mid-session",
       [](Effects& e) { e.bias_jump = {2.0, 0.0, -1.5}; }},
      {"turntable_bias", "outside: while the table turns the zero-g level shifts by (0.8, -0.5, -1.0) counts",
       [](Effects& e) { e.turntable_bias = {0.8, -0.5, -1.0}; }},
      {"bias_walk", "not white: the zero-g level random-walks, K = 0.056 counts/sqrt(s) per axis (about 1 mg, "
                    "0.34 counts, over the ~37 s from one capture to the next)",
       [](Effects& e) { e.bias_walk = {0.056, 0.056, 0.056}; }},
      {"settling", "not white: 0.5 % of each axis' response lags a pose change, relaxing with tau = 15 s; each "
                   "capture starts 15-20 s after its pose change",
       [](Effects& e) { e.settle_fraction = {0.005, 0.005, 0.005}; }},
      {"flicker", "not white: flicker (1/f) bias noise of instability B = 0.5 counts per axis (Allan floor "
                  "0.33 counts, about 1 mg)",
       [](Effects& e) { e.flicker = {0.5, 0.5, 0.5}; }},
  };
  return cases;
}

std::string Format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

// --- generate --------------------------------------------------------------------------------
int Generate(const std::vector<std::string>& args) {
  std::string plan_name = "seed", case_name = "clean", out_path, truth_path;
  unsigned long long seed = 1;
  double static_s = 10.0, turntable_s = 10.0;
  bool fixed_sensor = false;
  Sensor sensor;
  Bench bench;
  Effects overrides;
  std::set<std::string> overridden;
  std::optional<Eigen::Vector3d> noise;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= args.size()) Usage(a + " needs a value");
      return args[++i];
    };
    if (a == "--plan") plan_name = value();
    else if (a == "--case") case_name = value();
    else if (a == "--seed") seed = static_cast<unsigned long long>(ParseNumber(value()));
    else if (a == "-o") out_path = value();
    else if (a == "--truth") truth_path = value();
    else if (a == "--gravity") bench.gravity_mps2 = ParseNumber(value());
    else if (a == "--static-s") static_s = ParseNumber(value());
    else if (a == "--turntable-s") turntable_s = ParseNumber(value());
    else if (a == "--rate") sensor.rate_hz = ParseNumber(value());
    else if (a == "--noise") noise = ParseVector(value());
    else if (a == "--placement-deg") bench.placement_error_deg = ParseNumber(value());
    else if (a == "--gap") {
      const std::string v = value();
      const size_t comma = v.find(',');
      if (comma == std::string::npos) Usage("--gap MIN,MAX");
      bench.gap_min_s = ParseNumber(v.substr(0, comma));
      bench.gap_max_s = ParseNumber(v.substr(comma + 1));
    } else if (a == "--temperature") {
      const std::string v = value();
      const size_t comma = v.find(',');
      if (comma == std::string::npos) Usage("--temperature START,END");
      bench.temp_start_c = ParseNumber(v.substr(0, comma));
      bench.temp_end_c = ParseNumber(v.substr(comma + 1));
    } else if (a == "--warmup-tau") bench.warmup_tau_s = ParseNumber(value());
    else if (a == "--no-temperature") bench.temperature = false;
    else if (a == "--no-quantize") sensor.quantize = false;
    else if (a == "--fixed-sensor") fixed_sensor = true;
    else if (a == "--quadratic") { overrides.quadratic = ParseVector(value()); overridden.insert(a); }
    else if (a == "--temp-bias") { overrides.temp_bias = ParseVector(value()); overridden.insert(a); }
    else if (a == "--temp-scale") { overrides.temp_scale = ParseVector(value()); overridden.insert(a); }
    else if (a == "--drift") { overrides.drift = ParseVector(value()); overridden.insert(a); }
    else if (a == "--radius-offset") { overrides.radius_offset_m = ParseNumber(value()); overridden.insert(a); }
    else if (a == "--rpm-scale") { overrides.rpm_scale = ParseNumber(value()); overridden.insert(a); }
    else if (a == "--size") { overrides.size_effect_m = ParseVector(value()); overridden.insert(a); }
    else if (a == "--cubic") { overrides.cubic = ParseVector(value()); overridden.insert(a); }
    else if (a == "--cross") { overrides.cross_x_yz = ParseNumber(value()); overridden.insert(a); }
    else if (a == "--tilt-deg") { overrides.tilt_rad = ParseNumber(value()) * kPi / 180.0; overridden.insert(a); }
    else if (a == "--asym") { overrides.asym_scale = ParseVector(value()); overridden.insert(a); }
    else if (a == "--bias-jump") { overrides.bias_jump = ParseVector(value()); overridden.insert(a); }
    else if (a == "--turntable-bias") { overrides.turntable_bias = ParseVector(value()); overridden.insert(a); }
    else if (a == "--bias-walk") { overrides.bias_walk = ParseVector(value()); overridden.insert(a); }
    else if (a == "--flicker") { overrides.flicker = ParseVector(value()); overridden.insert(a); }
    else if (a == "--settle") { overrides.settle_fraction = ParseVector(value()); overridden.insert(a); }
    else if (a == "--settle-tau") { overrides.settle_tau_s = ParseNumber(value()); overridden.insert(a); }
    else if (a == "--settle-lead") { overrides.settle_lead_s = ParseNumber(value()); overridden.insert(a); }
    else Usage("unknown argument '" + a + "'");
  }
  if (out_path.empty()) Usage("generate needs -o SET.csv");

  Effects effects;
  const Case* chosen = nullptr;
  for (const Case& c : Cases())
    if (case_name == c.name) chosen = &c;
  if (!chosen) Usage("unknown case '" + case_name + "' (accelcal_physgen cases)");
  chosen->apply(effects);
  if (overridden.count("--quadratic")) effects.quadratic = overrides.quadratic;
  if (overridden.count("--temp-bias")) effects.temp_bias = overrides.temp_bias;
  if (overridden.count("--temp-scale")) effects.temp_scale = overrides.temp_scale;
  if (overridden.count("--drift")) effects.drift = overrides.drift;
  if (overridden.count("--radius-offset")) effects.radius_offset_m = overrides.radius_offset_m;
  if (overridden.count("--rpm-scale")) effects.rpm_scale = overrides.rpm_scale;
  if (overridden.count("--size")) effects.size_effect_m = overrides.size_effect_m;
  if (overridden.count("--cubic")) effects.cubic = overrides.cubic;
  if (overridden.count("--cross")) effects.cross_x_yz = overrides.cross_x_yz;
  if (overridden.count("--tilt-deg")) effects.tilt_rad = overrides.tilt_rad;
  if (overridden.count("--asym")) effects.asym_scale = overrides.asym_scale;
  if (overridden.count("--bias-jump")) effects.bias_jump = overrides.bias_jump;
  if (overridden.count("--turntable-bias")) effects.turntable_bias = overrides.turntable_bias;
  if (overridden.count("--bias-walk")) effects.bias_walk = overrides.bias_walk;
  if (overridden.count("--flicker")) effects.flicker = overrides.flicker;
  if (overridden.count("--settle")) effects.settle_fraction = overrides.settle_fraction;
  if (overridden.count("--settle-tau")) effects.settle_tau_s = overrides.settle_tau_s;
  if (overridden.count("--settle-lead")) effects.settle_lead_s = overrides.settle_lead_s;
  if (!(effects.settle_tau_s > 0.0) || !(effects.settle_lead_s >= 0.0))
    Usage("--settle-tau must be positive and --settle-lead not negative");

  std::vector<CaptureSpec> plan;
  if (plan_name == "seed") plan = physgen::SeedPlan(static_s, turntable_s);
  else if (plan_name == "rich") plan = physgen::RichPlan(static_s, turntable_s);
  else Usage("unknown plan '" + plan_name + "' (seed or rich)");

  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + 12345);
  if (!fixed_sensor) sensor = physgen::DrawSensor(sensor, rng);
  if (noise) sensor.noise_counts = *noise;
  const physgen::CaptureSetData set = physgen::Generate(sensor, effects, bench, plan, rng);

  std::ofstream out(out_path);
  if (!out) Usage("cannot write " + out_path);
  physgen::WriteCsv(set, out);
  out.close();
  if (!out) { std::cerr << "accelcal_physgen: writing " << out_path << " failed\n"; return 1; }
  if (!truth_path.empty()) {
    std::ofstream truth(truth_path);
    if (!truth) Usage("cannot write " + truth_path);
    physgen::WriteTruthJson(set,
                            {{"plan", plan_name}, {"case", case_name}, {"seed", std::to_string(seed)}},
                            truth);
    if (!truth) { std::cerr << "accelcal_physgen: writing " << truth_path << " failed\n"; return 1; }
  }
  return 0;
}

// --- compare ---------------------------------------------------------------------------------
nlohmann::json ReadJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) Usage("cannot read " + path);
  try {
    return nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    std::cerr << "accelcal_physgen: " << path << ": " << e.what() << "\n";
    std::exit(1);
  }
}

// Output (tab-separated, one line):
//   adopted   comma-separated names of cal.json's effects, or "-"
//   wrong     how many adopted effects are not the injected one (an out-of-library effect counts
//             as named when the adopted name contains its stem: cubic, cross, tilt)
//   named     1 when every injected effect was adopted, else 0 ("-" for the clean case)
//   chi2      cal.json fit.chi2_per_dof (of the final model)
//   z x 9     (est - truth) / sigma for bias_x..z, scale_x..z, a_yz, a_zy, a_zx
//   effect_z  max |est - truth| / sigma over the injected effects' parameters that cal.json
//             reports under the same names, or "nan"
int Compare(const std::vector<std::string>& args) {
  if (args.size() != 2) Usage("compare TRUTH.json CAL.json");
  const nlohmann::json truth = ReadJson(args[0]);
  const nlohmann::json cal = ReadJson(args[1]);
  std::vector<double> z;
  for (const char* key : {"bias_counts", "scale_counts_per_mps2"})
    for (int j = 0; j < 3; ++j)
      z.push_back((cal[key][j].get<double>() - truth[key][j].get<double>()) /
                  cal["uncertainty"][key][j].get<double>());
  for (const char* a : {"yz", "zy", "zx"})
    z.push_back((cal["misalignment_rad"][a].get<double>() - truth["misalignment_rad"][a].get<double>()) /
                cal["uncertainty"]["misalignment_rad"][a].get<double>());

  std::set<std::string> injected;
  std::map<std::string, std::string> stems = {{"cubic_nonlinearity", "cubic"},
                                              {"cross_axis_coupling", "cross"},
                                              {"turntable_tilt", "tilt"}};
  for (const auto& [name, _] : truth["effects"].items()) injected.insert(name);
  std::string adopted;
  int wrong = 0;
  std::set<std::string> found;
  double effect_z = NAN;
  for (const nlohmann::json& e : cal["effects"]) {
    const std::string name = e["name"].get<std::string>();
    adopted += (adopted.empty() ? "" : ",") + name;
    std::string match;
    for (const std::string& inj : injected) {
      if (name == inj) match = inj;
      else if (stems.count(inj) && name.find(stems[inj]) != std::string::npos) match = inj;
    }
    if (match.empty()) {
      ++wrong;
      continue;
    }
    found.insert(match);
    for (const auto& [p, v] : truth["effects"][match]["parameters"].items()) {
      if (!e["parameters"].contains(p) || !e["uncertainty"].contains(p)) continue;
      if (!e["parameters"][p].is_number() || !e["uncertainty"][p].is_number()) continue;
      const double zz = std::fabs(e["parameters"][p].get<double>() - v.get<double>()) /
                        e["uncertainty"][p].get<double>();
      if (std::isnan(effect_z) || zz > effect_z) effect_z = zz;
    }
  }
  std::cout << (adopted.empty() ? "-" : adopted) << "\t" << wrong << "\t"
            << (injected.empty() ? "-" : (found.size() == injected.size() ? "1" : "0")) << "\t"
            << Format("%.4g", cal["fit"]["chi2_per_dof"].get<double>());
  for (double v : z) std::cout << "\t" << Format("%.4g", v);
  std::cout << "\t" << Format("%.4g", effect_z) << "\n";
  return 0;
}

// --- selfcheck: the generator against the physics, computed here from the equations ---------
int failures = 0;

void Check(bool ok, const std::string& what) {
  std::cout << (ok ? "ok    " : "FAIL  ") << what << "\n";
  if (!ok) ++failures;
}

Eigen::Vector3d MeanRaw(const physgen::CaptureData& c) {
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (const physgen::Sample& s : c.samples) m += s.raw_counts;
  return m / static_cast<double>(c.samples.size());
}

// a^p = T K^-1 (raw - b), written again here from docs/model.md's equation.
Eigen::Vector3d Calibrate(const Sensor& s, const Eigen::Vector3d& raw) {
  return s.Misalignment() * s.scale_counts_per_mps2.cwiseInverse().asDiagonal() * (raw - s.bias_counts);
}

double Omega(double rpm) { return rpm * 2.0 * kPi / 60.0; }

int SelfCheck() {
  Sensor sensor;  // the default bench's sensor, distinct per axis, non-zero misalignment
  sensor.quantize = false;
  Bench bench;
  bench.placement_error_deg = 0.0;
  const double g = bench.gravity_mps2;
  const std::vector<CaptureSpec> plan = physgen::SeedPlan(60.0, 60.0);
  const Eigen::Matrix3d t = sensor.Misalignment();
  const Eigen::Matrix3d k = sensor.scale_counts_per_mps2.asDiagonal();

  // 1. The convention of the turntable: +x radial, +z up reads (-w^2 r, 0, g).
  {
    std::mt19937_64 rng(1);
    const physgen::CaptureSetData set = physgen::Generate(sensor, Effects{}, bench, plan, rng);
    const physgen::CaptureData& c = set.captures[11];  // +x radial, +z up, 0.15 m
    const double w = Omega(120.0);
    const Eigen::Vector3d f = physgen::SpecificForce(set, c, c.start_s + 1.234, -1);
    Check((f - Eigen::Vector3d(-w * w * 0.15, 0.0, g)).norm() < 1e-12,
          "turntable +x radial, +z up: f = (-w^2 r, 0, g) = (" + Format("%.4f", f.x()) + ", " +
              Format("%.4f", f.y()) + ", " + Format("%.4f", f.z()) + ") m/s^2 (toward the axis)");
    const physgen::CaptureData& cz = set.captures[17];  // +z radial, +x up, 0.15 m
    const Eigen::Vector3d fz = physgen::SpecificForce(set, cz, cz.start_s + 0.5, -1);
    Check((fz - Eigen::Vector3d(g, 0.0, -w * w * 0.15)).norm() < 1e-12,
          "turntable +z radial, +x up: f = (g, 0, -w^2 r)");

    // 2. Every clean static capture's mean reading is K T^-1 f + b within 4 sigma of the noise.
    double worst = 0.0;
    for (const physgen::CaptureData& cap : set.captures) {
      if (cap.spec.kind != physgen::Kind::kStatic) continue;
      const Eigen::Vector3d expected = k * t.inverse() * (g * cap.spec.up) + sensor.bias_counts;
      const Eigen::Vector3d sigma = sensor.noise_counts / std::sqrt(static_cast<double>(cap.samples.size()));
      worst = std::max(worst, ((MeanRaw(cap) - expected).cwiseQuotient(sigma)).cwiseAbs().maxCoeff());
    }
    Check(worst < 4.0, "static means = K T^-1 (g up) + b: worst " + Format("%.2f", worst) + " sigma");

    // 3. Every clean turntable capture's mean through the true model has |a^p| = sqrt(g^2 + (w^2 r)^2).
    worst = 0.0;
    double worst_radial = 0.0;
    for (const physgen::CaptureData& cap : set.captures) {
      if (cap.spec.kind != physgen::Kind::kTurntable) continue;
      const double c2 = std::pow(Omega(cap.spec.rpm), 2) * cap.spec.radius_m;
      const Eigen::Vector3d ap = Calibrate(sensor, MeanRaw(cap));
      // 1-sigma of |a^p|: the noise of the mean, in m/s^2, along the force's direction.
      const double sigma = (sensor.noise_counts.cwiseQuotient(sensor.scale_counts_per_mps2)).norm() /
                           std::sqrt(3.0 * static_cast<double>(cap.samples.size()));
      worst = std::max(worst, std::fabs(ap.norm() - std::hypot(g, c2)) / sigma);
      worst_radial = std::max(worst_radial,
                              std::fabs(ap.dot(physgen::AxisVector(cap.spec.radial_axis)) + c2) / sigma);
    }
    Check(worst < 4.0, "turntable |T K^-1 (mean - b)| = sqrt(g^2 + (w^2 r)^2): worst " +
                           Format("%.2f", worst) + " sigma");
    Check(worst_radial < 4.0, "turntable radial component = -w^2 r: worst " +
                                  Format("%.2f", worst_radial) + " sigma");
  }

  // 4. Quantization and the ADC: rounded readings keep the mean (noise 1.5 counts dithers).
  {
    Sensor q = sensor;
    q.quantize = true;
    std::mt19937_64 rng(2);
    const physgen::CaptureSetData set = physgen::Generate(q, Effects{}, bench, plan, rng);
    double worst = 0.0;
    bool integer = true;
    for (const physgen::CaptureData& cap : set.captures) {
      for (const physgen::Sample& s : cap.samples)
        integer = integer && s.raw_counts == s.raw_counts.array().round().matrix();
      if (cap.spec.kind != physgen::Kind::kStatic) continue;
      const Eigen::Vector3d expected = k * t.inverse() * (g * cap.spec.up) + q.bias_counts;
      const Eigen::Vector3d sigma = q.noise_counts / std::sqrt(static_cast<double>(cap.samples.size()));
      worst = std::max(worst, ((MeanRaw(cap) - expected).cwiseQuotient(sigma)).cwiseAbs().maxCoeff());
    }
    Check(integer && worst < 4.0, "quantized: whole counts, static means within " +
                                      Format("%.2f", worst) + " sigma of K T^-1 f + b");
  }

  // 5. The tilted table: mean magnitude sqrt((g cos th)^2 + (w^2 r)^2), and a once-per-revolution
  //    swing of amplitude g sin th in the sensor frame (least-squares sine at the stated rpm).
  {
    Effects e;
    e.tilt_rad = 2.0 * kPi / 180.0;
    Sensor quiet = sensor;
    quiet.noise_counts = Eigen::Vector3d::Constant(1e-9);
    std::mt19937_64 rng(3);
    const physgen::CaptureSetData set = physgen::Generate(quiet, e, bench, plan, rng);
    const physgen::CaptureData& cap = set.captures[11];  // +x radial, +z up, 0.15 m, 120 rpm
    const double w = Omega(120.0);
    const double c2 = w * w * 0.15;
    const Eigen::Vector3d ap_mean = Calibrate(quiet, MeanRaw(cap));
    const double expected = std::hypot(g * std::cos(e.tilt_rad), c2);
    Check(std::fabs(ap_mean.norm() - expected) < 1e-6,
          "tilt 2 deg: mean |a^p| = sqrt((g cos th)^2 + (w^2 r)^2) = " + Format("%.6f", expected) +
              " (got " + Format("%.6f", ap_mean.norm()) + "; untilted " + Format("%.6f", std::hypot(g, c2)) + ")");
    // Sine fit of the tangential (sensor y) component: y(t) = A cos(w t) + B sin(w t) + C.
    const long n = static_cast<long>(cap.samples.size());
    Eigen::MatrixXd design(n, 3);
    Eigen::VectorXd y(n);
    double scatter = 0.0;
    for (long i = 0; i < n; ++i) {
      const double tt = cap.samples[i].t_s - cap.start_s;
      design.row(i) << std::cos(w * tt), std::sin(w * tt), 1.0;
      y(i) = Calibrate(quiet, cap.samples[i].raw_counts).y();
      scatter += y(i) * y(i);
    }
    const Eigen::Vector3d abc = design.colPivHouseholderQr().solve(y);
    const double amplitude = std::hypot(abc(0), abc(1));
    Check(std::fabs(amplitude - g * std::sin(e.tilt_rad)) < 1e-6,
          "tilt 2 deg: tangential swing once per revolution, amplitude " + Format("%.4f", amplitude) +
              " m/s^2 = g sin th; per-sample std " + Format("%.4f", std::sqrt(scatter / n)) +
              " m/s^2 (noise: " + Format("%.4f", 1.5 / 34.8) + ")");
  }

  // 6. The sizes of the effects outside the library, as the issue states them.
  {
    Effects cubic;
    cubic.cubic = {1e-4, 0.0, 0.0};
    Effects cross;
    cross.cross_x_yz = 0.03;
    std::mt19937_64 rng(4);
    const physgen::CaptureSetData clean = physgen::Generate(sensor, Effects{}, bench, plan, rng);
    physgen::CaptureSetData with_cubic = clean;
    with_cubic.effects = cubic;
    physgen::CaptureSetData with_cross = clean;
    with_cross.effects = cross;
    const physgen::CaptureData& tt = clean.captures[11];
    const double w = Omega(120.0);
    const double u = (t.inverse() * Eigen::Vector3d(-w * w * 0.15, 0.0, g)).x();
    const double d_cubic = (physgen::NoiseFreeReading(with_cubic, tt, tt.start_s) -
                            physgen::NoiseFreeReading(clean, tt, tt.start_s)).x();
    Check(std::fabs(d_cubic - 1e-4 * u * u * u) < 1e-9,
          "cubic 1e-4: " + Format("%.3f", d_cubic) + " counts = " +
              Format("%.1f", 1000.0 * std::fabs(d_cubic) / sensor.scale_counts_per_mps2.x()) +
              " mm/s^2 on x at u_x = " + Format("%.2f", u) + " m/s^2 (" + Format("%.2f", std::fabs(u) / g) + " g)");
    const physgen::CaptureData& corner = clean.captures[6];  // tilted +x+y+z
    const Eigen::Vector3d ua = t.inverse() * (g * corner.spec.up);
    const double d_cross = (physgen::NoiseFreeReading(with_cross, corner, corner.start_s) -
                            physgen::NoiseFreeReading(clean, corner, corner.start_s)).x();
    Check(std::fabs(d_cross - 0.03 * ua.y() * ua.z()) < 1e-9,
          "cross 0.03: " + Format("%.3f", d_cross) + " counts = " +
              Format("%.1f", 1000.0 * d_cross / sensor.scale_counts_per_mps2.x()) +
              " mm/s^2 on x at the (1,1,1) corner");
  }

  // 7. The in-library effects against their definitions.
  {
    std::mt19937_64 rng(5);
    const physgen::CaptureSetData clean = physgen::Generate(sensor, Effects{}, bench, plan, rng);
    // Radius offset and rpm scale: the magnitude of the true force follows r + dr, (1 + s) w.
    physgen::CaptureSetData geo = clean;
    geo.effects.radius_offset_m = 0.003;
    geo.effects.rpm_scale = 0.01;
    const physgen::CaptureData& tt = geo.captures[10];  // +x radial, 0.10 m
    const double w = 1.01 * Omega(120.0);
    const Eigen::Vector3d ap = Calibrate(sensor, physgen::NoiseFreeReading(geo, tt, tt.start_s + 2.0));
    Check(std::fabs(ap.norm() - std::hypot(g, w * w * 0.103)) < 1e-9,
          "radius offset 3 mm + rpm 1 %: |a^p| = sqrt(g^2 + ((1.01 w)^2 (r + dr))^2)");
    // Size effect: the in-plane axes feel -w^2 d_j extra along themselves, the vertical none.
    physgen::CaptureSetData size = clean;
    size.effects.size_effect_m = {0.0015, -0.001, 0.002};
    const double w0 = Omega(120.0);
    Eigen::Vector3d da = (size.sensor.scale_counts_per_mps2.cwiseInverse().asDiagonal() *
                          (physgen::NoiseFreeReading(size, tt, tt.start_s) -
                           physgen::NoiseFreeReading(clean, tt, tt.start_s)));
    // a^a_j extra = (T^-1 (-w^2 d_j e_j in the plane))_j: for +x radial, +z up, x and y in plane.
    const Eigen::Vector3d expect_x = t.inverse() * Eigen::Vector3d(-w0 * w0 * 0.0015, 0, 0);
    const Eigen::Vector3d expect_y = t.inverse() * Eigen::Vector3d(0, w0 * w0 * 0.001, 0);
    Check(std::fabs(da.x() - expect_x.x()) < 1e-9 && std::fabs(da.y() - expect_y.y()) < 1e-9 &&
              std::fabs(da.z()) < 1e-12,
          "size effect: in-plane axes -w^2 d_j extra (x " + Format("%.4f", da.x()) + ", y " +
              Format("%.4f", da.y()) + " m/s^2), vertical z none");
    // Temperature bias and drift are relative to the captures' mean temperature and time: their
    // offsets average to zero over the captures.
    physgen::CaptureSetData temp = clean;
    temp.effects.temp_bias = {0.5, -0.3, 0.8};
    temp.effects.drift = {0.002, 0.0, -0.001};
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double tmin = 1e9, tmax = -1e9;
    for (const physgen::CaptureData& c : temp.captures) {
      Eigen::Vector3d d = Eigen::Vector3d::Zero();
      for (const physgen::Sample& s : c.samples)
        d += physgen::NoiseFreeReading(temp, c, s.t_s) - physgen::NoiseFreeReading(clean, c, s.t_s);
      sum += d / static_cast<double>(c.samples.size());
      tmin = std::min(tmin, physgen::TrueTemperatureC(bench, c.start_s));
      tmax = std::max(tmax, physgen::TrueTemperatureC(bench, c.samples.back().t_s));
    }
    Check(sum.norm() < 1e-6, "temperature bias and drift average to zero over the captures "
                             "(references: mean time " + Format("%.1f", temp.t_ref_s) + " s, mean temperature " +
                             Format("%.2f", temp.temp_ref_c) + " degC; temperature " + Format("%.1f", tmin) +
                             ".." + Format("%.1f", tmax) + " degC)");
  }
  // 8. What the truth states of the coupling and the tilt (the quantities a magnitude fit sees),
  //    and the effects outside the library against their definitions.
  {
    std::mt19937_64 rng(6);
    const physgen::CaptureSetData clean = physgen::Generate(sensor, Effects{}, bench, plan, rng);
    physgen::CaptureSetData cross = clean;
    cross.effects.cross_x_yz = 0.03;
    const physgen::CaptureData& corner = clean.captures[6];  // tilted +x+y+z
    const Eigen::Vector3d ua = t.inverse() * (g * corner.spec.up);
    const double kappa = 0.03 / sensor.scale_counts_per_mps2.x();
    const double d_mag = Calibrate(sensor, physgen::NoiseFreeReading(cross, corner, corner.start_s)).norm() -
                         Calibrate(sensor, physgen::NoiseFreeReading(clean, corner, corner.start_s)).norm();
    const double first_order = kappa * ua.x() * ua.y() * ua.z() / ua.norm();
    Check(std::fabs(d_mag - first_order) < 0.02 * std::fabs(first_order),
          "cross 0.03: |a^p| grows by kappa u_x u_y u_z / |u| = " + Format("%.5f", first_order) +
              " m/s^2 at the corner, kappa = c_x / k_x = " + Format("%.3g", kappa) + " (got " +
              Format("%.5f", d_mag) + ")");
    // Asymmetric scale: +x and -x faces read k (1 + a) g and -k (1 - a) g beyond the bias.
    physgen::CaptureSetData asym = clean;
    asym.effects.asym_scale = {0.003, 0.0, 0.0};
    const physgen::CaptureData& px = clean.captures[2];  // +x up
    const physgen::CaptureData& mx = clean.captures[3];  // -x up
    const double kx = sensor.scale_counts_per_mps2.x();
    const double up_x = (physgen::NoiseFreeReading(asym, px, px.start_s) - sensor.bias_counts).x();
    const double down_x = (physgen::NoiseFreeReading(asym, mx, mx.start_s) - sensor.bias_counts).x();
    const double ux_p = (t.inverse() * (g * px.spec.up)).x(), ux_m = (t.inverse() * (g * mx.spec.up)).x();
    Check(std::fabs(up_x - kx * 1.003 * ux_p) < 1e-9 && std::fabs(down_x - kx * 0.997 * ux_m) < 1e-9,
          "asymmetric scale 0.003: +x face reads k (1 + a) u, -x face k (1 - a) u");
    // Bias jump: samples after t_jump carry it, those before do not.
    physgen::CaptureSetData jump = clean;
    jump.effects.bias_jump = {2.0, 0.0, -1.5};
    const physgen::CaptureData& first = clean.captures.front();
    const physgen::CaptureData& last = clean.captures.back();
    const Eigen::Vector3d before = physgen::NoiseFreeReading(jump, first, first.start_s) -
                                   physgen::NoiseFreeReading(clean, first, first.start_s);
    const Eigen::Vector3d after = physgen::NoiseFreeReading(jump, last, last.start_s) -
                                  physgen::NoiseFreeReading(clean, last, last.start_s);
    Check(before.norm() < 1e-12 && (after - jump.effects.bias_jump).norm() < 1e-12 &&
              clean.jump_t_s > first.start_s && clean.jump_t_s < last.start_s,
          "bias jump: (2, 0, -1.5) counts from t = " + Format("%.1f", clean.jump_t_s) +
              " s on, none before");
    // Turntable bias: the runs shift, the static poses do not.
    physgen::CaptureSetData vre = clean;
    vre.effects.turntable_bias = {0.8, -0.5, -1.0};
    const physgen::CaptureData& run = clean.captures[10];
    const Eigen::Vector3d on_run = physgen::NoiseFreeReading(vre, run, run.start_s + 1.0) -
                                   physgen::NoiseFreeReading(clean, run, run.start_s + 1.0);
    const Eigen::Vector3d on_face = physgen::NoiseFreeReading(vre, first, first.start_s) -
                                    physgen::NoiseFreeReading(clean, first, first.start_s);
    Check((on_run - vre.effects.turntable_bias).norm() < 1e-12 && on_face.norm() < 1e-12,
          "turntable bias: (0.8, -0.5, -1.0) counts on the runs, none on the static poses");
  }
  // 9. The world that is not white (issue 29): the random walk's increments, the flicker's Allan
  //    floor, the settling's lag, each computed here from its definition.
  {
    Sensor quiet = sensor;
    quiet.noise_counts.setZero();
    Effects walk;
    walk.bias_walk = {0.05, 0.1, 0.2};
    std::mt19937_64 rng(7);
    const physgen::CaptureSetData set = physgen::Generate(quiet, walk, bench, plan, rng);
    Eigen::Vector3d sum_sq = Eigen::Vector3d::Zero(), mean_of_means = Eigen::Vector3d::Zero();
    long steps = 0;
    double dt = 0.0;
    for (const physgen::CaptureData& c : set.captures) {
      const physgen::CaptureData& clean_c = c;
      Eigen::Vector3d m = Eigen::Vector3d::Zero();
      for (size_t i = 0; i < c.samples.size(); ++i) {
        const Eigen::Vector3d off = c.samples[i].raw_counts - physgen::NoiseFreeReading(set, clean_c, c.samples[i].t_s);
        m += off;
        if (i == 0) continue;
        const Eigen::Vector3d prev = c.samples[i - 1].raw_counts -
                                     physgen::NoiseFreeReading(set, clean_c, c.samples[i - 1].t_s);
        sum_sq += (off - prev).cwiseAbs2();
        dt = c.samples[i].t_s - c.samples[i - 1].t_s;
        ++steps;
      }
      mean_of_means += m / static_cast<double>(c.samples.size());
    }
    const Eigen::Vector3d k_est = (sum_sq / static_cast<double>(steps) / dt).cwiseSqrt();
    Check(((k_est - walk.bias_walk).cwiseQuotient(walk.bias_walk)).cwiseAbs().maxCoeff() < 0.02 &&
              mean_of_means.norm() < 1e-9,
          "bias random walk K = (0.05, 0.1, 0.2) counts/sqrt(s): increments give (" + Format("%.4f", k_est.x()) +
              ", " + Format("%.4f", k_est.y()) + ", " + Format("%.4f", k_est.z()) +
              "); its mean over the captures is 0");

    // Flicker: the overlapping Allan deviation of a long record (one 2000 s capture, no noise)
    // at 1, 4 and 16 s against 0.664 B = sqrt(2 ln 2 / pi) B.
    Effects flicker;
    flicker.flicker = {0.5, 0.5, 0.5};
    std::vector<CaptureSpec> one = {plan.front()};
    one.front().duration_s = 2000.0;
    double worst = 0.0;
    std::string figures;
    for (int seed = 1; seed <= 3; ++seed) {
      std::mt19937_64 frng(static_cast<unsigned long long>(seed));
      const physgen::CaptureSetData fs = physgen::Generate(quiet, flicker, bench, one, frng);
      const physgen::CaptureData& c = fs.captures.front();
      for (int j = 0; j < 3; ++j) {
        std::vector<double> y;
        for (const physgen::Sample& smp : c.samples) y.push_back(smp.raw_counts(j) - NoiseFreeReading(fs, c, smp.t_s)(j));
        for (long m : {100L, 400L, 1600L}) {
          std::vector<double> csum(y.size() + 1, 0.0);
          for (size_t i = 0; i < y.size(); ++i) csum[i + 1] = csum[i] + y[i];
          double acc = 0.0;
          long terms = 0;
          for (size_t i = 0; i + 2 * m <= y.size(); ++i, ++terms) {
            const double a = (csum[i + m] - csum[i]) / m, b = (csum[i + 2 * m] - csum[i + m]) / m;
            acc += 0.5 * (b - a) * (b - a);
          }
          const double adev = std::sqrt(acc / terms);
          worst = std::max(worst, std::fabs(adev / (0.664 * 0.5) - 1.0));
          if (seed == 1 && j == 0) figures += Format(" %.3f", adev);
        }
      }
    }
    Check(worst < 0.25, "flicker B = 0.5 counts: Allan deviation at 1, 4, 16 s" + figures +
                            " counts (0.664 B = 0.332; worst of 3 records x 3 axes " +
                            Format("%.0f %%", 100.0 * worst) + " off)");

    // Settling: the offset at a capture's first sample is eps k (u_lag(t_c) - u) exp(-lead / tau).
    Effects settle;
    settle.settle_fraction = {0.005, 0.005, 0.005};
    std::mt19937_64 srng(8);
    const physgen::CaptureSetData ss = physgen::Generate(sensor, settle, bench, plan, srng);
    physgen::CaptureSetData flat = ss;
    flat.effects = Effects{};
    const physgen::CaptureData& minus_z = ss.captures[1];  // after +z up: a 2 g step on z
    const double lead = minus_z.start_s - minus_z.change_s;
    const Eigen::Vector3d u_plus = t.inverse() * Eigen::Vector3d(0, 0, g), u_minus = t.inverse() * Eigen::Vector3d(0, 0, -g);
    const Eigen::Vector3d lag0 = u_plus + (ss.captures[0].lag_at_change - u_plus) *
                                              std::exp(-(minus_z.change_s - ss.captures[0].change_s) / 15.0);
    const double expect = 0.005 * sensor.scale_counts_per_mps2.z() * (lag0.z() - u_minus.z()) * std::exp(-lead / 15.0);
    const double got = (physgen::NoiseFreeReading(ss, minus_z, minus_z.start_s) -
                        physgen::NoiseFreeReading(flat, minus_z, minus_z.start_s)).z();
    const double later = (physgen::NoiseFreeReading(ss, minus_z, minus_z.start_s + 10.0) -
                          physgen::NoiseFreeReading(flat, minus_z, minus_z.start_s + 10.0)).z();
    Check(std::fabs(got - expect) < 1e-9 && std::fabs(later - expect * std::exp(-10.0 / 15.0)) < 1e-9 &&
              lead >= 15.0 - 1e-9 && lead <= 20.0 + 1e-9,
          "settling 0.5 %, tau 15 s: -z up after +z up starts " + Format("%.1f", lead) + " s after the change, z " +
              Format("%+.2f", got) + " counts off, " + Format("%+.2f", later) + " after 10 s");
  }
  std::cout << (failures ? "selfcheck FAILED\n" : "selfcheck passed\n");
  return failures ? 1 : 0;
}


// --- tally: the tables of evaluate.sh from its per-seed lines --------------------------------
// Input lines (tab-separated): case, seed, "ok", then compare's fields; or case, seed, "fail",
// the error. Cases are listed in the order they first appear.
double Median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int Tally(const std::vector<std::string>& args) {
  if (args.size() != 1) Usage("tally RESULTS.tsv");
  std::ifstream in(args[0]);
  if (!in) Usage("cannot read " + args[0]);
  struct Row {
    int runs = 0, fits = 0, wrong = 0, named = 0, named_known = 0;
    std::map<std::string, int> adopted;
    std::map<std::string, int> failures;
    std::vector<std::vector<double>> z = std::vector<std::vector<double>>(9);
    std::vector<double> effect_z, chi2;
  };
  std::vector<std::string> order;
  std::map<std::string, Row> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string item;
    while (std::getline(ss, item, '\t')) f.push_back(item);
    if (f.size() < 3) continue;
    if (!rows.count(f[0])) order.push_back(f[0]);
    Row& r = rows[f[0]];
    ++r.runs;
    if (f[2] != "ok") {
      std::string why = f.size() > 3 ? f[3] : "?";
      if (why.size() > 70) why = why.substr(0, 70) + "...";
      ++r.failures[why];
      continue;
    }
    if (f.size() < 17) continue;
    ++r.fits;
    std::stringstream names(f[3]);
    std::set<std::string> seen;
    while (std::getline(names, item, ','))
      if (item != "-" && seen.insert(item).second) ++r.adopted[item];
    r.wrong += std::stoi(f[4]) > 0;
    if (f[5] != "-") {
      ++r.named_known;
      r.named += f[5] == "1";
    }
    r.chi2.push_back(std::stod(f[6]));
    for (int k = 0; k < 9; ++k) r.z[k].push_back(std::fabs(std::stod(f[7 + k])));
    const double ez = std::stod(f[16]);
    if (!std::isnan(ez)) r.effect_z.push_back(ez);
  }

  std::printf("Effects adopted (per case: seeds with a fit; seeds adopting a wrong effect; seeds\n"
              "naming the injected one; each adopted effect's seed count; median |est - truth| /\n"
              "sigma of the injected effect's parameters where named)\n\n");
  std::printf("%-18s %7s %7s %7s %8s  %s\n", "case", "fits", "wrong", "named", "eff |z|", "adopted");
  for (const std::string& c : order) {
    const Row& r = rows.at(c);
    std::string adopted;
    for (const auto& [name, n] : r.adopted)
      adopted += (adopted.empty() ? "" : ", ") + name + " " + std::to_string(n);
    for (const auto& [why, n] : r.failures)
      adopted += (adopted.empty() ? "" : "; ") + std::string("FAILED ") + std::to_string(n) + ": " + why;
    if (adopted.empty()) adopted = "none";
    const std::string named = r.named_known ? std::to_string(r.named) + "/" + std::to_string(r.named_known) : "-";
    std::printf("%-18s %3d/%-3d %3d/%-3d %7s %8s  %s\n", c.c_str(), r.fits, r.runs, r.wrong, r.fits,
                named.c_str(), r.effect_z.empty() ? "-" : Format("%.2f", Median(r.effect_z)).c_str(),
                adopted.c_str());
  }

  static const char* kNames[9] = {"bias_x", "bias_y", "bias_z", "scale_x", "scale_y", "scale_z",
                                  "a_yz", "a_zy", "a_zx"};
  std::printf("\nThe nine parameters: median |est - truth| / sigma (sigma from cal.json) and the share\n"
              "of seeds beyond 3 sigma; chi2/dof of the final fit (cal.json fit.chi2_per_dof, median)\n\n");
  std::printf("%-18s", "case");
  for (const char* n : kNames) std::printf(" %11s", n);
  std::printf(" %8s\n", "chi2/dof");
  for (const std::string& c : order) {
    const Row& r = rows.at(c);
    std::printf("%-18s", c.c_str());
    for (int k = 0; k < 9; ++k) {
      if (r.z[k].empty()) {
        std::printf(" %11s", "-");
        continue;
      }
      int beyond = 0;
      for (double v : r.z[k]) beyond += v > 3.0;
      const double pct = 100.0 * beyond / static_cast<double>(r.z[k].size());
      std::printf(" %5.2f/%3.0f%%", Median(r.z[k]), pct);
    }
    std::printf(" %8.2f\n", Median(r.chi2));
  }

  std::printf("\nCoverage: the share of |est - truth| / sigma within 1, 2 and 3 over the nine parameters\n"
              "of every seed with a fit (a Gaussian gives 68.3 / 95.4 / 99.7 %%); the worst parameter's\n"
              "2-sigma share; seeds refused (no calibration, with the reason above)\n\n");
  std::printf("%-18s %7s %7s %7s %7s %8s %-20s %7s\n", "case", "fits", "1 sig", "2 sig", "3 sig", "n", "worst at 2 sig", "refused");
  for (const std::string& c : order) {
    const Row& r = rows.at(c);
    int within[3] = {0, 0, 0}, total = 0;
    double worst_share = 2.0;
    int worst_k = -1;
    for (int k = 0; k < 9; ++k) {
      int in2 = 0;
      for (double v : r.z[k]) {
        for (int m = 0; m < 3; ++m) within[m] += v <= m + 1.0;
        in2 += v <= 2.0;
        ++total;
      }
      const double share = r.z[k].empty() ? 2.0 : in2 / static_cast<double>(r.z[k].size());
      if (share < worst_share) { worst_share = share; worst_k = k; }
    }
    int refused = 0;
    for (const auto& [why, n] : r.failures) refused += n;
    if (total == 0) {
      std::printf("%-18s %3d/%-3d %7s %7s %7s %8d %-20s %7d\n", c.c_str(), r.fits, r.runs, "-", "-", "-", 0, "-", refused);
      continue;
    }
    const std::string worst = worst_k < 0 ? "-" : std::string(kNames[worst_k]) + " " + Format("%.0f %%", 100.0 * worst_share);
    std::printf("%-18s %3d/%-3d %6.1f%% %6.1f%% %6.1f%% %8d %-20s %7d\n", c.c_str(), r.fits, r.runs,
                100.0 * within[0] / total, 100.0 * within[1] / total, 100.0 * within[2] / total, total,
                worst.c_str(), refused);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) Usage("missing command");
  const std::string cmd = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  try {
    if (cmd == "generate") return Generate(args);
    if (cmd == "compare") return Compare(args);
    if (cmd == "selfcheck") return SelfCheck();
    if (cmd == "tally") return Tally(args);
    if (cmd == "means") return physgen::MeansCommand(args);
    if (cmd == "residuals") return physgen::ResidualsCommand(args);
    if (cmd == "cases") {
      for (const Case& c : Cases()) std::cout << c.name << "\t" << c.what << "\n";
      return 0;
    }
  } catch (const std::exception& e) {
    std::cerr << "accelcal_physgen: " << e.what() << "\n";
    return 1;
  }
  Usage("unknown command '" + cmd + "'");
}
