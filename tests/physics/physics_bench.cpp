// The independent bench of physics_bench.h: the standard library and Eigen only.
#include "physics_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <complex>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <unsupported/Eigen/FFT>

namespace physgen {
namespace {

constexpr double kPi = 3.14159265358979323846;

double RadPerS(double rpm) { return rpm * 2.0 * kPi / 60.0; }

// A small random rotation: each component of the rotation vector ~ N(0, sigma).
Eigen::Matrix3d SmallRotation(double sigma_rad, std::mt19937_64& rng) {
  if (sigma_rad <= 0.0) return Eigen::Matrix3d::Identity();
  std::normal_distribution<double> n(0.0, sigma_rad);
  const Eigen::Vector3d v(n(rng), n(rng), n(rng));
  const double angle = v.norm();
  if (angle == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, v / angle).toRotationMatrix();
}

std::string Num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string Short(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string Vec(const Eigen::Vector3d& v) {
  return "[" + Num(v.x()) + ", " + Num(v.y()) + ", " + Num(v.z()) + "]";
}

std::string Quoted(const std::string& s) {
  if (s.find_first_of(",\"") == std::string::npos) return s;
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"') out += '"';
    out += ch;
  }
  return out + "\"";
}

std::string JsonString(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch;
  }
  return out + "\"";
}

}  // namespace

Eigen::Matrix3d Sensor::Misalignment() const {
  Eigen::Matrix3d t;
  t << 1.0, -a_yz_rad, a_zy_rad,
       0.0, 1.0, -a_zx_rad,
       0.0, 0.0, 1.0;
  return t;
}

Eigen::Vector3d AxisVector(const std::string& axis) {
  if (axis.size() != 2 || (axis[0] != '+' && axis[0] != '-') || axis[1] < 'x' || axis[1] > 'z')
    throw std::invalid_argument("not a sensor axis: '" + axis + "' (+x ... -z)");
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  v(axis[1] - 'x') = axis[0] == '+' ? 1.0 : -1.0;
  return v;
}

Eigen::Matrix3d MountingRotation(const std::string& radial_axis, const std::string& up_axis) {
  const Eigen::Vector3d e_r = AxisVector(radial_axis);
  const Eigen::Vector3d e_u = AxisVector(up_axis);
  if (std::fabs(e_r.dot(e_u)) > 0.5)
    throw std::invalid_argument("radial and up axes must be perpendicular");
  Eigen::Matrix3d m;
  m.row(0) = e_r.transpose();
  m.row(1) = e_u.cross(e_r).transpose();
  m.row(2) = e_u.transpose();
  return m;
}

double TrueTemperatureC(const Bench& bench, double t_s) {
  if (bench.warmup_tau_s <= 0.0) return bench.temp_start_c;
  return bench.temp_end_c +
         (bench.temp_start_c - bench.temp_end_c) * std::exp(-std::max(t_s, 0.0) / bench.warmup_tau_s);
}

Eigen::Vector3d SpecificForce(const CaptureSetData& set, const CaptureData& c, double t_s, int j) {
  const double g = set.bench.gravity_mps2;
  const Eigen::Matrix3d& p = c.placement;  // v_ideal = P v_platform
  if (c.spec.kind == Kind::kStatic) {
    // At rest: f = -g_vec = g up; the operator's pose is "up" turned by the placement error.
    return p.transpose() * (g * c.spec.up.normalized());
  }
  const Eigen::Matrix3d m = MountingRotation(c.spec.radial_axis, c.spec.up_axis);
  const double w = (1.0 + set.effects.rpm_scale) * RadPerS(c.spec.rpm);
  const double phi = c.phase0_rad + w * (t_s - c.start_s);
  const double th = set.effects.tilt_rad;
  // World up in the table frame (spin axis tilted by th about world X, table turned by phi).
  const Eigen::Vector3d up_world(std::sin(th) * std::sin(phi), std::sin(th) * std::cos(phi),
                                 std::cos(th));
  Eigen::Vector3d pos(c.spec.radius_m + set.effects.radius_offset_m, 0.0, 0.0);
  if (j >= 0) pos += m * p * (set.effects.size_effect_m(j) * Eigen::Vector3d::Unit(j));
  // Constant rate: the acceleration is centripetal, toward the axis; f = a + g up_world.
  const Eigen::Vector3d f_table =
      Eigen::Vector3d(-w * w * pos.x(), -w * w * pos.y(), 0.0) + g * up_world;
  return p.transpose() * m.transpose() * f_table;
}

Eigen::Vector3d NoiseFreeReading(const CaptureSetData& set, const CaptureData& c, double t_s) {
  const Sensor& s = set.sensor;
  const Effects& e = set.effects;
  const Eigen::Matrix3d t_inv = s.Misalignment().inverse();
  Eigen::Vector3d u;
  for (int j = 0; j < 3; ++j) u(j) = (t_inv * SpecificForce(set, c, t_s, j))(j);  // a^a_j
  const double dtemp = TrueTemperatureC(set.bench, t_s) - set.temp_ref_c;
  const double dt = t_s - set.t_ref_s;
  Eigen::Vector3d raw;
  for (int j = 0; j < 3; ++j) {
    const double sign = u(j) > 0.0 ? 1.0 : (u(j) < 0.0 ? -1.0 : 0.0);
    double response = s.scale_counts_per_mps2(j) * u(j) * (1.0 + e.asym_scale(j) * sign) +
                      e.quadratic(j) * u(j) * u(j) + e.cubic(j) * u(j) * u(j) * u(j);
    if (j == 0) response += e.cross_x_yz * u(1) * u(2);
    raw(j) = s.bias_counts(j) + e.drift(j) * dt + e.temp_bias(j) * dtemp +
             (1.0 + e.temp_scale(j) * dtemp) * response;
    if (t_s >= set.jump_t_s) raw(j) += e.bias_jump(j);
    if (c.spec.kind == Kind::kTurntable) raw(j) += e.turntable_bias(j);
    if (e.settle_fraction(j) != 0.0) {
      const double lag = (c.lag_at_change(j) - c.pose_u(j)) *
                         std::exp(-std::max(0.0, t_s - c.change_s) / e.settle_tau_s);
      raw(j) += e.settle_fraction(j) * s.scale_counts_per_mps2(j) * lag;
    }
  }
  return raw;
}

namespace {

// The mean input u = a^a (m/s^2) of capture c over its samples (the settling's pose input).
Eigen::Vector3d MeanInput(const CaptureSetData& set, const CaptureData& c) {
  const Eigen::Matrix3d t_inv = set.sensor.Misalignment().inverse();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Sample& smp : c.samples)
    for (int j = 0; j < 3; ++j) sum(j) += (t_inv * SpecificForce(set, c, smp.t_s, j))(j);
  return sum / static_cast<double>(c.samples.size());
}

// Settling: each capture's pose change, its input and the lagging input at the change (the
// header comment's recursion; before the session the sensor rests +z up).
void ScheduleSettling(CaptureSetData* set, const std::vector<double>& gaps_before_s) {
  const Effects& e = set->effects;
  Eigen::Vector3d u_prev = set->sensor.Misalignment().inverse() *
                           Eigen::Vector3d(0.0, 0.0, set->bench.gravity_mps2);
  Eigen::Vector3d lag_prev = u_prev;
  double change_prev_s = 0.0;
  for (size_t i = 0; i < set->captures.size(); ++i) {
    CaptureData& c = set->captures[i];
    c.pose_u = MeanInput(*set, c);
    c.change_s = c.start_s - std::min(gaps_before_s[i], e.settle_lead_s);
    const double decay = std::exp(-std::max(0.0, c.change_s - change_prev_s) / e.settle_tau_s);
    c.lag_at_change = u_prev + (lag_prev - u_prev) * decay;
    u_prev = c.pose_u;
    lag_prev = c.lag_at_change;
    change_prev_s = c.change_s;
  }
}

// Kasdin's 1/f noise (alpha = 1) of n points with white innovations of std b: FFT convolution
// of w_n with h_0 = 1, h_k = h_{k-1} (k - 1/2) / k.
std::vector<double> FlickerSeries(long n, double b, std::mt19937_64& rng) {
  std::normal_distribution<double> unit(0.0, 1.0);
  long m = 1;
  while (m < 2 * n) m *= 2;
  std::vector<double> w(static_cast<size_t>(m), 0.0), h(static_cast<size_t>(m), 0.0);
  for (long k = 0; k < n; ++k) w[static_cast<size_t>(k)] = b * unit(rng);
  h[0] = 1.0;
  for (long k = 1; k < n; ++k)
    h[static_cast<size_t>(k)] = h[static_cast<size_t>(k - 1)] * (static_cast<double>(k) - 0.5) / static_cast<double>(k);
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> wf, hf;
  fft.fwd(wf, w);
  fft.fwd(hf, h);
  for (size_t k = 0; k < wf.size(); ++k) wf[k] *= hf[k];
  std::vector<double> x;
  fft.inv(x, wf);
  x.resize(static_cast<size_t>(n));
  return x;
}

// The bias processes at every sample of every capture (random walk + flicker, per axis), less
// their mean over the captures.
void GenerateWander(CaptureSetData* set, std::mt19937_64& rng) {
  const Effects& e = set->effects;
  if (e.bias_walk.isZero() && e.flicker.isZero()) return;
  const double dt = 1.0 / set->sensor.rate_hz;
  const double end_s = set->captures.back().samples.back().t_s;
  const long n = static_cast<long>(std::ceil(end_s / dt)) + 2;
  std::normal_distribution<double> unit(0.0, 1.0);
  std::vector<double> walk[3], flick[3];
  for (int j = 0; j < 3; ++j) {
    walk[j].assign(static_cast<size_t>(n), 0.0);
    if (e.bias_walk(j) != 0.0)
      for (long k = 1; k < n; ++k)
        walk[j][static_cast<size_t>(k)] = walk[j][static_cast<size_t>(k - 1)] + e.bias_walk(j) * std::sqrt(dt) * unit(rng);
    flick[j] = e.flicker(j) != 0.0 ? FlickerSeries(n, e.flicker(j), rng) : std::vector<double>(static_cast<size_t>(n), 0.0);
  }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (CaptureData& c : set->captures) {
    Eigen::Vector3d cm = Eigen::Vector3d::Zero();
    for (const Sample& smp : c.samples) {
      const size_t k = static_cast<size_t>(std::clamp<long>(std::lround(smp.t_s / dt), 0, n - 1));
      const Eigen::Vector3d v(walk[0][k] + flick[0][k], walk[1][k] + flick[1][k], walk[2][k] + flick[2][k]);
      c.wander_counts.push_back(v);
      cm += v;
    }
    mean += cm / static_cast<double>(c.samples.size());
  }
  mean /= static_cast<double>(set->captures.size());
  for (CaptureData& c : set->captures)
    for (Eigen::Vector3d& v : c.wander_counts) v -= mean;
}

}  // namespace

CaptureSetData Generate(const Sensor& sensor, const Effects& effects, const Bench& bench,
                        const std::vector<CaptureSpec>& plan, std::mt19937_64& rng) {
  CaptureSetData set;
  set.sensor = sensor;
  set.effects = effects;
  set.bench = bench;
  std::uniform_real_distribution<double> gap(bench.gap_min_s, bench.gap_max_s);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * kPi);
  const double dt = 1.0 / sensor.rate_hz;

  // 1. The schedule: start times, placements, phases; the references.
  double t = bench.first_start_s;
  double t_sum = 0.0, temp_sum = 0.0;
  std::vector<double> gaps_before_s;  // for the first capture: the sensor rested since t = 0
  for (const CaptureSpec& spec : plan) {
    gaps_before_s.push_back(set.captures.empty() ? t : t - set.captures.back().samples.back().t_s);
    CaptureData c;
    c.spec = spec;
    c.start_s = t;
    c.placement = SmallRotation(bench.placement_error_deg * kPi / 180.0, rng);
    c.phase0_rad = phase(rng);
    const long n = std::lround(spec.duration_s * sensor.rate_hz);
    double ct = 0.0, ctemp = 0.0;
    for (long i = 0; i < n; ++i) {
      Sample smp;
      smp.t_s = c.start_s + static_cast<double>(i) * dt;
      ct += smp.t_s;
      ctemp += TrueTemperatureC(bench, smp.t_s);
      c.samples.push_back(smp);
    }
    t_sum += ct / static_cast<double>(n);
    temp_sum += ctemp / static_cast<double>(n);
    t = c.samples.back().t_s + gap(rng);
    set.captures.push_back(std::move(c));
  }
  set.t_ref_s = t_sum / static_cast<double>(plan.size());
  set.temp_ref_c = temp_sum / static_cast<double>(plan.size());
  if (!set.captures.empty()) {
    const size_t middle = set.captures.size() / 2;
    set.jump_t_s = middle == 0 ? set.captures[0].start_s - 1.0
                               : 0.5 * (set.captures[middle - 1].samples.back().t_s +
                                        set.captures[middle].start_s);
  }

  // 2. The settling's schedule and the bias processes (a stream of their own, so that turning
  //    them on leaves the rest of the data as it was).
  if (!effects.settle_fraction.isZero()) ScheduleSettling(&set, gaps_before_s);

  // 3. The samples.
  std::mt19937_64 rng_copy = rng;  // the main stream is not advanced by the bias processes
  std::mt19937_64 wander_rng(rng_copy() ^ 0x5851f42d4c957f2dULL);
  GenerateWander(&set, wander_rng);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (CaptureData& c : set.captures) {
    for (size_t i = 0; i < c.samples.size(); ++i) {
      Sample& smp = c.samples[i];
      Eigen::Vector3d raw = NoiseFreeReading(set, c, smp.t_s);
      if (!c.wander_counts.empty()) raw += c.wander_counts[i];
      for (int j = 0; j < 3; ++j) {
        raw(j) += sensor.noise_counts(j) * unit(rng);
        if (sensor.quantize) raw(j) = std::clamp(std::round(raw(j)), sensor.adc_min, sensor.adc_max);
      }
      smp.raw_counts = raw;
      smp.temp_c = TrueTemperatureC(bench, smp.t_s) + bench.temp_noise_c * unit(rng);
    }
  }
  return set;
}

void WriteCsv(const CaptureSetData& set, std::ostream& out) {
  out << "# accelcal capture set\n";
  out << "# generated by accelcal_physgen (tests/physics): an independent bench\n";
  if (set.sensor.quantize)
    out << "# adc_range_counts = " << Num(set.sensor.adc_min) << "," << Num(set.sensor.adc_max)
        << "\n";
  out << "capture,kind,t,ax,ay,az,temp_c,radius_m,rpm,label,up_axis\n";
  char buf[256];
  int id = 0;
  for (const CaptureData& c : set.captures) {
    ++id;
    const bool tt = c.spec.kind == Kind::kTurntable;
    for (const Sample& s : c.samples) {
      out << id << (tt ? ",turntable," : ",static,");
      std::snprintf(buf, sizeof buf, "%.4f,", s.t_s);
      out << buf;
      for (int j = 0; j < 3; ++j) {
        if (set.sensor.quantize)
          std::snprintf(buf, sizeof buf, "%.0f,", s.raw_counts(j));
        else
          std::snprintf(buf, sizeof buf, "%.6f,", s.raw_counts(j));
        out << buf;
      }
      if (set.bench.temperature) {
        std::snprintf(buf, sizeof buf, "%.2f", s.temp_c);
        out << buf;
      }
      out << ",";
      if (tt) out << Short(c.spec.radius_m) << "," << Short(c.spec.rpm) << ",";
      else out << ",,";
      out << Quoted(c.spec.label) << "," << (tt ? c.spec.up_axis : "") << "\n";
    }
  }
}

void WriteTruthJson(const CaptureSetData& set, const std::map<std::string, std::string>& info,
                    std::ostream& out) {
  const Sensor& s = set.sensor;
  const Effects& e = set.effects;
  out << "{\n  \"generator\": \"accelcal_physgen\",\n";
  for (const auto& [k, v] : info) out << "  " << JsonString(k) << ": " << JsonString(v) << ",\n";
  out << "  \"gravity_mps2\": " << Num(set.bench.gravity_mps2) << ",\n";
  out << "  \"bias_counts\": " << Vec(s.bias_counts) << ",\n";
  out << "  \"scale_counts_per_mps2\": " << Vec(s.scale_counts_per_mps2) << ",\n";
  out << "  \"misalignment_rad\": {\"yz\": " << Num(s.a_yz_rad) << ", \"zy\": " << Num(s.a_zy_rad)
      << ", \"zx\": " << Num(s.a_zx_rad) << "},\n";
  out << "  \"noise_counts\": " << Vec(s.noise_counts) << ",\n";
  out << "  \"rate_hz\": " << Num(s.rate_hz) << ",\n";
  out << "  \"reference\": {\"t_s\": " << Num(set.t_ref_s) << ", \"temp_c\": " << Num(set.temp_ref_c)
      << "},\n";
  out << "  \"captures\": " << set.captures.size() << ",\n";
  // Effects: name -> {parameter: value}; "library": whether accelcal's library has it today.
  std::vector<std::string> items;
  auto per_axis = [&](const char* name, const char* stem, const Eigen::Vector3d& v, bool lib) {
    if (v.isZero()) return;
    std::string body = "    " + JsonString(name) + ": {\"library\": " + (lib ? "true" : "false") +
                       ", \"parameters\": {";
    for (int j = 0; j < 3; ++j)
      body += std::string(j ? ", " : "") + "\"" + stem + "_" + "xyz"[j] + "\": " + Num(v(j));
    items.push_back(body + "}}");
  };
  auto scalar = [&](const char* name, const char* param, double v, bool lib) {
    if (v == 0.0) return;
    items.push_back("    " + JsonString(name) + ": {\"library\": " + (lib ? "true" : "false") +
                    ", \"parameters\": {" + JsonString(param) + ": " + Num(v) + "}}");
  };
  per_axis("quadratic_nonlinearity", "q", e.quadratic, true);
  per_axis("temperature_bias", "tc_bias", e.temp_bias, true);
  per_axis("temperature_scale", "tc_scale", e.temp_scale, true);
  per_axis("bias_drift", "drift", e.drift, true);
  scalar("radius_offset", "dr", e.radius_offset_m, true);
  scalar("rpm_scale", "rpm_scale", e.rpm_scale, true);
  per_axis("size_effect", "d", e.size_effect_m, true);
  per_axis("cubic_nonlinearity", "c3", e.cubic, true);
  if (e.cross_x_yz != 0.0) {
    // The magnitude-equivalent coupling of the header comment: kappa = c_x / k_x.
    items.push_back("    \"cross_axis_coupling\": {\"library\": true, \"parameters\": {\"c_x_yz\": " +
                    Num(e.cross_x_yz) + ", \"kappa\": " + Num(e.cross_x_yz / s.scale_counts_per_mps2.x()) +
                    "}}");
  }
  if (e.tilt_rad != 0.0) {
    items.push_back("    \"turntable_tilt\": {\"library\": true, \"parameters\": {\"tilt_rad\": " +
                    Num(e.tilt_rad) + ", \"tilt_loss\": " + Num(1.0 - std::cos(e.tilt_rad)) + "}}");
  }
  per_axis("asymmetric_scale", "asym", e.asym_scale, false);
  per_axis("bias_jump", "jump", e.bias_jump, false);
  per_axis("turntable_bias", "vre", e.turntable_bias, false);
  per_axis("bias_walk", "K", e.bias_walk, false);
  per_axis("flicker", "B", e.flicker, false);
  per_axis("settling", "eps", e.settle_fraction, false);
  out << "  \"effects\": {";
  for (size_t i = 0; i < items.size(); ++i) out << (i ? ",\n" : "\n") << items[i];
  out << (items.empty() ? "}\n" : "\n  }\n") << "}\n";
}

namespace {

CaptureSpec Static(const std::string& label, Eigen::Vector3d up, double duration_s) {
  CaptureSpec c;
  c.kind = Kind::kStatic;
  c.label = label;
  c.up = up.normalized();
  c.duration_s = duration_s;
  return c;
}

CaptureSpec Turntable(const std::string& radial, const std::string& up, double r, double rpm,
                      double duration_s) {
  CaptureSpec c;
  c.kind = Kind::kTurntable;
  c.radial_axis = radial;
  c.up_axis = up;
  c.radius_m = r;
  c.rpm = rpm;
  c.duration_s = duration_s;
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s radial, %s up, r = %.2f m, %.0f rpm", radial.c_str(),
                up.c_str(), r, rpm);
  c.label = buf;
  return c;
}

std::string SignLabel(const Eigen::Vector3d& v) {
  std::string s;
  for (int j = 0; j < 3; ++j) {
    if (v(j) == 0.0) continue;
    s += v(j) > 0 ? "+" : "-";
    s += "xyz"[j];
  }
  return s;
}

}  // namespace

std::vector<CaptureSpec> SeedPlan(double static_s, double turntable_s) {
  std::vector<CaptureSpec> plan;
  const char* faces[] = {"+z", "-z", "+x", "-x", "+y", "-y"};
  for (const char* f : faces) plan.push_back(Static(std::string(f) + " up", AxisVector(f), static_s));
  for (const Eigen::Vector3d& v :
       {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 1, -1), Eigen::Vector3d(1, -1, 1)})
    plan.push_back(Static("tilted " + SignLabel(v), v, static_s));
  const std::pair<const char*, const char*> mounts[] = {{"+x", "+z"}, {"+y", "+z"}, {"+z", "+x"}};
  for (const auto& [radial, up] : mounts)
    for (double r : {0.05, 0.10, 0.15}) plan.push_back(Turntable(radial, up, r, 120.0, turntable_s));
  return plan;
}

std::vector<CaptureSpec> RichPlan(double static_s, double turntable_s) {
  std::vector<CaptureSpec> plan;
  // 26 directions: faces (one non-zero component), edges (two), corners (three).
  for (int nonzero = 1; nonzero <= 3; ++nonzero)
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z) {
          if (std::abs(x) + std::abs(y) + std::abs(z) != nonzero) continue;
          const Eigen::Vector3d v(x, y, z);
          plan.push_back(Static((nonzero == 1 ? "" : "tilted ") + SignLabel(v) + (nonzero == 1 ? " up" : ""),
                                v, static_s));
        }
  const std::pair<const char*, const char*> mounts[] = {{"+x", "+z"}, {"-x", "+z"}, {"+y", "+z"},
                                                        {"-y", "+z"}, {"+z", "+x"}, {"-z", "+x"}};
  const std::pair<double, double> runs[] = {{0.05, 120}, {0.10, 120}, {0.15, 120}, {0.10, 90}, {0.15, 150}};
  for (const auto& [radial, up] : mounts)
    for (const auto& [r, rpm] : runs) plan.push_back(Turntable(radial, up, r, rpm, turntable_s));
  return plan;
}

Sensor DrawSensor(const Sensor& nominal, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Sensor s = nominal;
  for (int j = 0; j < 3; ++j) {
    s.bias_counts(j) = 2048.0 + 20.0 * u(rng);
    s.scale_counts_per_mps2(j) = 34.8 * (1.0 + 0.02 * u(rng));
  }
  s.a_yz_rad = 0.008 * u(rng);
  s.a_zy_rad = 0.008 * u(rng);
  s.a_zx_rad = 0.008 * u(rng);
  return s;
}

}  // namespace physgen
