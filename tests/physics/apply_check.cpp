// accelcal_physgen means / residuals: does a written calibration, applied by `accelcal apply`
// to its own captures' mean readings, give back the residuals its fit reported?
//
//   accelcal_physgen means SET.csv CAL.json > MEANS.txt     one line "t ax ay az temp_c" per
//                                                           capture: its mean reading, less the
//                                                           session's bias drift (apply does not
//                                                           remove it)
//   accelcal apply CAL.json < MEANS.txt > APPLIED.txt
//   accelcal_physgen residuals SET.csv CAL.json APPLIED.txt prints each used capture's
//                                                           |a| - |f| and the file's residual;
//                                                           exit 1 when one differs by > 1e-5
//
// What `apply` leaves out is added here from docs/model.md's definitions of the bench's effects,
// written again (not the project's code): the size effect (axis j in the table's plane feels
// -w^2 d_j extra, so its a^a gains w^2 d_j back, a^a = T^-1 a^p), and the reference
// |f| = sqrt((g (1 - tilt_loss))^2 + (w^2 (r + dr))^2), w = (1 + rpm_scale) rpm 2 pi / 60.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "physics_bench.h"

namespace physgen {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct SetCapture {
  int id = 0;
  bool turntable = false;
  double radius_m = 0.0, rpm = 0.0;
  std::string up_axis;
  long n = 0;
  double t_sum = 0.0, temp_sum = 0.0;
  Eigen::Vector3d raw_sum = Eigen::Vector3d::Zero();
};

// The fields of one CSV row, quotes undone (the project's capture-set format).
std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted) {
      if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') { out.back() += '"'; ++i; }
      else if (ch == '"') quoted = false;
      else out.back() += ch;
    } else if (ch == '"') quoted = true;
    else if (ch == ',') out.emplace_back();
    else if (ch != '\r') out.back() += ch;
  }
  return out;
}

// The captures of a set written by `generate` (columns in its order), with their sums.
std::vector<SetCapture> ReadSet(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<SetCapture> caps;
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) { header = true; continue; }
    const std::vector<std::string> f = SplitCsv(line);
    if (f.size() != 11) throw std::runtime_error(path + ": a row without 11 fields");
    const int id = std::stoi(f[0]);
    if (caps.empty() || caps.back().id != id) {
      caps.emplace_back();
      caps.back().id = id;
      caps.back().turntable = f[1] == "turntable";
      if (caps.back().turntable) {
        caps.back().radius_m = std::stod(f[7]);
        caps.back().rpm = std::stod(f[8]);
        caps.back().up_axis = f[10];
      }
    }
    SetCapture& c = caps.back();
    ++c.n;
    c.t_sum += std::stod(f[2]);
    c.raw_sum += Eigen::Vector3d(std::stod(f[3]), std::stod(f[4]), std::stod(f[5]));
    c.temp_sum += f[6].empty() ? NAN : std::stod(f[6]);
  }
  return caps;
}

nlohmann::json ReadJsonFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  return nlohmann::json::parse(in);
}

// Parameter `p` of the calibration's effect `name`, 0 when the effect was not adopted.
double EffectParameter(const nlohmann::json& cal, const std::string& name, const std::string& p) {
  for (const nlohmann::json& e : cal["effects"])
    if (e["name"] == name) return e["parameters"][p].get<double>();
  return 0.0;
}

Eigen::Vector3d EffectTriple(const nlohmann::json& cal, const std::string& name, const std::string& stem) {
  return {EffectParameter(cal, name, stem + "_x"), EffectParameter(cal, name, stem + "_y"),
          EffectParameter(cal, name, stem + "_z")};
}

Eigen::Matrix3d MisalignmentOf(const nlohmann::json& cal) {
  Sensor s;
  s.a_yz_rad = cal["misalignment_rad"]["yz"].get<double>();
  s.a_zy_rad = cal["misalignment_rad"]["zy"].get<double>();
  s.a_zx_rad = cal["misalignment_rad"]["zx"].get<double>();
  return s.Misalignment();
}

}  // namespace

int MeansCommand(const std::vector<std::string>& args) {
  if (args.size() != 2) throw std::invalid_argument("means SET.csv CAL.json");
  const std::vector<SetCapture> caps = ReadSet(args[0]);
  const nlohmann::json cal = ReadJsonFile(args[1]);
  const Eigen::Vector3d drift = EffectTriple(cal, "bias_drift", "drift");
  // Each effect carries the reference point it was fitted at (the same for all of a file's).
  const double t_ref = cal["effects"].empty() ? 0.0 : cal["effects"][0]["reference"]["t_s"].get<double>();
  for (const SetCapture& c : caps) {
    const double t = c.t_sum / c.n;
    const Eigen::Vector3d raw = c.raw_sum / c.n - drift * (t - t_ref);
    std::printf("%.10g %.12g %.12g %.12g", t, raw.x(), raw.y(), raw.z());
    if (!std::isnan(c.temp_sum)) std::printf(" %.12g", c.temp_sum / c.n);
    std::printf("\n");
  }
  return 0;
}

int ResidualsCommand(const std::vector<std::string>& args) {
  if (args.size() != 3) throw std::invalid_argument("residuals SET.csv CAL.json APPLIED.txt");
  const std::vector<SetCapture> caps = ReadSet(args[0]);
  const nlohmann::json cal = ReadJsonFile(args[1]);
  std::ifstream applied(args[2]);
  if (!applied) throw std::runtime_error("cannot read " + args[2]);
  std::vector<Eigen::Vector3d> ap;
  std::string line;
  while (std::getline(applied, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double t;
    Eigen::Vector3d a;
    fields >> t >> a.x() >> a.y() >> a.z();
    ap.push_back(a);
  }
  if (ap.size() != caps.size()) throw std::runtime_error("APPLIED.txt: one line per capture expected");
  const double g = cal["gravity_mps2"].get<double>();
  const double dr = EffectParameter(cal, "radius_offset", "dr");
  const double s = EffectParameter(cal, "rpm_scale", "rpm_scale");
  const double loss = EffectParameter(cal, "turntable_tilt", "tilt_loss");
  const Eigen::Vector3d d = EffectTriple(cal, "size_effect", "d");
  const Eigen::Matrix3d t = MisalignmentOf(cal);
  std::map<int, const nlohmann::json*> listed;
  for (const nlohmann::json& c : cal["captures"]) listed[c["id"].get<int>()] = &c;
  double worst = 0.0;
  int compared = 0;
  for (size_t i = 0; i < caps.size(); ++i) {
    const SetCapture& c = caps[i];
    const nlohmann::json& rec = *listed.at(c.id);
    if (!rec["used"].get<bool>()) continue;
    Eigen::Vector3d a = ap[i];
    double reference = g;
    if (c.turntable) {
      const double w = (1.0 + s) * c.rpm * 2.0 * kPi / 60.0;
      Eigen::Vector3d u = t.inverse() * a;  // a^a
      const Eigen::Vector3d up = AxisVector(c.up_axis);
      for (int j = 0; j < 3; ++j) u(j) += w * w * d(j) * (1.0 - up(j) * up(j));
      a = t * u;
      reference = std::hypot(g * (1.0 - loss), w * w * (c.radius_m + dr));
    }
    const double mine = a.norm() - reference;
    const double theirs = rec["residual_mps2"].get<double>();
    std::printf("capture %2d  |a| - |f| %+.6f  file %+.6f  diff %+.2e\n", c.id, mine, theirs, mine - theirs);
    worst = std::max(worst, std::fabs(mine - theirs));
    ++compared;
  }
  std::printf("%d captures compared, largest difference %.3g m/s^2\n", compared, worst);
  return compared > 0 && worst <= 1e-5 ? 0 : 1;
}

}  // namespace physgen
