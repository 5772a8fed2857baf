#include "accelcal/acquire/sim/virtual_bench.h"

#include <algorithm>
#include <cmath>

#include "accelcal/base/error.h"

namespace accelcal::sim {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

// The bias noise's stream is seeded from the bench seed mixed with this constant (any fixed odd
// number), so it is independent of the main stream and reproducible.
constexpr std::uint64_t kBiasNoiseSeedMix = 0xd1b54a32d192ed03ULL;

// Platform -> table rotation for a turntable mounting: radial_axis -> x_table, up_axis ->
// z_table, and (up x radial) -> (z x x) = y_table, which keeps the rotation proper.
Eigen::Matrix3d MountingRotation(SensorAxis radial, SensorAxis up) {
  const Eigen::Vector3d e_r = SensorAxisVector(radial);
  const Eigen::Vector3d e_u = SensorAxisVector(up);
  Eigen::Matrix3d sensor_axes;
  sensor_axes << e_r, e_u, e_u.cross(e_r);
  Eigen::Matrix3d table_axes;
  table_axes << Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY();
  return table_axes * sensor_axes.transpose();
}

// Table -> world rotation of a table whose +x side dips by tilt_deg.y() and whose +y side dips
// by tilt_deg.x() (the leveling convention): turning about world y by +a lowers +x; turning
// about world x by +b raises +y.
Eigen::Matrix3d TableRotation(const Eigen::Vector2d& tilt_deg) {
  if (tilt_deg.isZero()) return Eigen::Matrix3d::Identity();
  return (Eigen::AngleAxisd(tilt_deg.y() * kDegToRad, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(-tilt_deg.x() * kDegToRad, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// The scenario, or accelcal::Error when scenario.Validate() finds a problem (before any member
// is built from it).
Scenario ValidScenario(Scenario scenario) {
  if (std::string why = scenario.Validate(); !why.empty()) {
    throw Error(scenario.source_name + ": " + why);
  }
  // One sensor's bench: a plate of boards is not simulated by it (issue 31: the fixture bench
  // comes next), and is refused rather than simulated as one sensor.
  if (scenario.fixture) {
    throw Error(scenario.source_name + ": its [fixture] of " +
                std::to_string(scenario.fixture->boards.size()) +
                " boards is not simulated yet: the virtual bench holds one sensor");
  }
  return scenario;
}

}  // namespace

double SampleTimeS(double start_s, long k, double rate_hz) {
  return std::round((start_s + static_cast<double>(k) / rate_hz) * 1e6) / 1e6;
}

Eigen::Matrix3d RotationBetween(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  return Eigen::Quaterniond::FromTwoVectors(from, to).toRotationMatrix();
}

Eigen::Vector3d ActivePulse::AccelerationWorld(double t_s) const {
  const double tau = (t_s - start_s) / duration_s;
  if (tau < 0.0 || tau > 1.0) return Eigen::Vector3d::Zero();
  return peak_world_mps2 * std::sin(M_PI * tau);
}

VirtualBench::VirtualBench(Scenario scenario)
    : scenario_(ValidScenario(std::move(scenario))),
      rng_(scenario_.bench.seed),
      bias_noise_(scenario_.sensor.bias_noise, scenario_.bench.seed ^ kBiasNoiseSeedMix),
      table_tilt_deg_(scenario_.bench.table_tilt_deg),
      turntable_tilt_rad_(scenario_.effects.turntable_tilt_rad) {
  session_duration_s_ = scenario_.SessionDurationS();
}

void VirtualBench::AdjustTableFeet(const Eigen::Vector2d& correction_deg) {
  table_tilt_deg_ -= correction_deg;
}

void VirtualBench::LevelTurntable(double keep) { turntable_tilt_rad_ *= keep; }

void VirtualBench::Reseed(std::uint64_t seed) {
  rng_.seed(seed);
  bias_noise_.Reset(seed ^ kBiasNoiseSeedMix);
  lagged_t_s_ = kNaN;
}

// First order: the lagging part moves toward the ideal reading by 1 - exp(-dt / tau) over dt
// (a reading earlier than the last one sees it unchanged).
Eigen::Vector3d VirtualBench::Settle(const Eigen::Vector3d& ideal_counts, double t_s) {
  const Eigen::Vector3d& share = scenario_.effects.settling_share;
  if (share.isZero()) return ideal_counts;
  if (std::isnan(lagged_t_s_)) {
    lagged_counts_ = ideal_counts;
    lagged_t_s_ = t_s;
  } else if (t_s > lagged_t_s_) {
    lagged_counts_ += (ideal_counts - lagged_counts_) * (1.0 - std::exp(-(t_s - lagged_t_s_) / scenario_.effects.settling_tau_s));
    lagged_t_s_ = t_s;
  }
  return ideal_counts - share.cwiseProduct(ideal_counts - lagged_counts_);
}

Eigen::Matrix3d VirtualBench::RandomPlacementRotation() {
  std::normal_distribution<double> unit;
  const double sigma_rad = scenario_.bench.placement_error_deg * kDegToRad;
  // Draw all three components even when sigma is zero, so the stream does not depend on it.
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v(i) = sigma_rad * unit(rng_);
  const double angle = v.norm();
  if (angle == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, v / angle).toRotationMatrix();
}

Mounting VirtualBench::BeginCapture(const CapturePlan& plan, double start_s) {
  Mounting m;
  m.kind = plan.kind;
  m.start_s = start_s;
  if (plan.kind == CaptureKind::kStatic) {
    // R * up = table z: world-up seen from the platform is `up` on a level table; turned about
    // the table's normal by the yaw, tilted with the table.
    m.platform_rotation = RotationBetween(plan.up, Eigen::Vector3d::UnitZ()) * RandomPlacementRotation();
    if (plan.yaw_rad != 0.0)
      m.platform_rotation = Eigen::AngleAxisd(plan.yaw_rad, Eigen::Vector3d::UnitZ()) * m.platform_rotation;
    m.platform_rotation = TableRotation(table_tilt_deg_) * m.platform_rotation;
    return m;
  }
  m.platform_rotation =
      MountingRotation(plan.radial_axis, plan.up_axis) * RandomPlacementRotation();
  m.true_radius_m = plan.radius_m + scenario_.effects.radius_offset_m;
  m.omega_rad_per_s = RpmToRadPerS(plan.rpm) * (1.0 + scenario_.effects.rpm_scale);
  m.phase_rad = std::uniform_real_distribution<double>(0.0, 2.0 * M_PI)(rng_);
  m.turntable_tilt_rad = turntable_tilt_rad_;
  return m;
}

Mounting VirtualBench::StopTurntable(const Mounting& running, double t_s) const {
  Mounting m;
  m.kind = CaptureKind::kStatic;
  m.start_s = t_s;
  if (running.kind != CaptureKind::kTurntable) {
    m.platform_rotation = running.platform_rotation;
    return m;
  }
  // Platform to world as SpecificForceAt turns it: table to world after the seat.
  const double angle = running.phase_rad + running.omega_rad_per_s * (t_s - running.start_s);
  m.platform_rotation = Eigen::AngleAxisd(running.turntable_tilt_rad, Eigen::Vector3d::UnitX()) *
                        Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()) * running.platform_rotation;
  return m;
}

Mounting VirtualBench::BeginCapture(int plan_index, double start_s) {
  Mounting m = BeginCapture(scenario_.captures.at(static_cast<std::size_t>(plan_index)), start_s);
  for (const Bump& bump : scenario_.effects.bumps) {
    if (bump.capture != plan_index) continue;
    const double heading = std::uniform_real_distribution<double>(0.0, 2.0 * M_PI)(rng_);
    ActivePulse p;
    p.start_s = start_s + bump.at_s;
    p.duration_s = bump.duration_s;
    p.peak_world_mps2 = bump.peak_mps2 * Eigen::Vector3d(std::cos(heading), std::sin(heading), 0.0);
    m.pulses.push_back(p);
  }
  return m;
}

Eigen::Vector3d VirtualBench::PulseAccelerationWorld(const Mounting& mounting, double t_s) const {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  for (const ActivePulse& p : mounting.pulses) a += p.AccelerationWorld(t_s);
  return a;
}

Eigen::Vector3d VirtualBench::SpecificForceAt(const Mounting& mounting, double t_s,
                                              const Eigen::Vector3d& offset_platform_m) const {
  const double g = scenario_.bench.gravity_mps2;
  // f = a - gravity = a + g z_world, in the world frame.
  const Eigen::Vector3d f_world_rigid =
      g * Eigen::Vector3d::UnitZ() + PulseAccelerationWorld(mounting, t_s);
  if (mounting.kind == CaptureKind::kStatic) {
    return mounting.platform_rotation.transpose() * f_world_rigid;
  }
  const double angle = mounting.phase_rad + mounting.omega_rad_per_s * (t_s - mounting.start_s);
  const Eigen::Matrix3d table_to_world =
      Eigen::AngleAxisd(mounting.turntable_tilt_rad, Eigen::Vector3d::UnitX()) *
      Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  // Position of the point in the table frame; constant rate, so the only kinematic
  // acceleration is centripetal, towards the spin axis: -w^2 times the in-plane position.
  const Eigen::Vector3d p_table = mounting.true_radius_m * Eigen::Vector3d::UnitX() +
                                  mounting.platform_rotation * offset_platform_m;
  const double w2 = mounting.omega_rad_per_s * mounting.omega_rad_per_s;
  const Eigen::Vector3d centripetal_table(-w2 * p_table.x(), -w2 * p_table.y(), 0.0);
  const Eigen::Vector3d f_table = centripetal_table + table_to_world.transpose() * f_world_rigid;
  return mounting.platform_rotation.transpose() * f_table;
}

Eigen::Vector3d VirtualBench::SpecificForcePlatform(const Mounting& mounting, double t_s) const {
  return SpecificForceAt(mounting, t_s, Eigen::Vector3d::Zero());
}

Eigen::Matrix3d VirtualBench::SpecificForcePerAxis(const Mounting& mounting, double t_s) const {
  const Eigen::Vector3d& d = scenario_.effects.size_effect_m;
  Eigen::Matrix3d f;
  for (int i = 0; i < 3; ++i) {
    f.col(i) = SpecificForceAt(mounting, t_s, d(i) * Eigen::Vector3d::Unit(i));
  }
  return f;
}

double VirtualBench::TemperatureC(double t_s) const {
  const std::optional<TemperatureRamp>& ramp = scenario_.effects.temperature;
  if (!ramp) return scenario_.bench.temperature_c;
  if (ramp->warmup_tau_s > 0.0)
    return ramp->start_c + (ramp->end_c - ramp->start_c) * (1.0 - std::exp(-std::max(t_s, 0.0) / ramp->warmup_tau_s));
  const double fraction =
      session_duration_s_ > 0.0 ? std::clamp(t_s / session_duration_s_, 0.0, 1.0) : 0.0;
  return ramp->start_c + (ramp->end_c - ramp->start_c) * fraction;
}

Eigen::Vector3d VirtualBench::IdealRaw(const Eigen::Matrix3d& f_per_axis_mps2, double t_s) const {
  const SensorModel& model = scenario_.sensor.model;
  const EffectsSpec& fx = scenario_.effects;
  const Eigen::Matrix3d t = model.Misalignment();
  // a^a = T^-1 a^p, axis by axis: axis i reads component i of what it feels where it sits.
  Eigen::Vector3d along_axes_mps2;
  for (int i = 0; i < 3; ++i) {
    along_axes_mps2(i) = t.triangularView<Eigen::UnitUpper>().solve(f_per_axis_mps2.col(i))(i);
  }
  const double delta_c = TemperatureC(t_s) - scenario_.bench.temperature_c;
  const Eigen::Vector3d scale = model.scale_counts_per_mps2.cwiseProduct(
      Eigen::Vector3d::Ones() + fx.scale_temp_coeff_per_c * delta_c);
  const Eigen::Vector3d bias = model.bias_counts + fx.bias_temp_coeff_counts_per_c * delta_c +
                               fx.bias_drift_counts_per_s * t_s;
  return scale.cwiseProduct(along_axes_mps2) +
         fx.quadratic_counts_per_mps2_sq.cwiseProduct(along_axes_mps2.cwiseAbs2()) + bias;
}

Sample VirtualBench::MeasurePerAxis(const Eigen::Matrix3d& f_per_axis_mps2, double t_s) {
  std::normal_distribution<double> unit;
  Eigen::Vector3d raw = Settle(IdealRaw(f_per_axis_mps2, t_s), t_s) + bias_noise_.Advance(t_s);
  for (int i = 0; i < 3; ++i) raw(i) += scenario_.sensor.noise_counts(i) * unit(rng_);
  const double lo = scenario_.adc.MinCounts();
  const double hi = scenario_.adc.MaxCounts();
  Sample s;
  s.t_s = t_s;
  for (int i = 0; i < 3; ++i) s.raw_counts(i) = std::clamp(std::round(raw(i)), lo, hi);
  s.temp_c = TemperatureC(t_s);
  return s;
}

Sample VirtualBench::Measure(const Eigen::Vector3d& f_platform_mps2, double t_s) {
  return MeasurePerAxis(f_platform_mps2.replicate<1, 3>(), t_s);
}

std::vector<Capture> VirtualBench::SimulateCaptureSet() {
  Reseed(scenario_.bench.seed);
  session_duration_s_ = scenario_.SessionDurationS();
  const double rate_hz = scenario_.sensor.rate_hz;
  std::vector<Capture> captures;
  double start_s = 0.0;
  for (int i = 0; i < static_cast<int>(scenario_.captures.size()); ++i) {
    const CapturePlan& plan = scenario_.captures[static_cast<std::size_t>(i)];
    const double duration_s = scenario_.CaptureDurationS(i);
    const Mounting mounting = BeginCapture(i, start_s);
    Capture c;
    c.id = i + 1;
    c.kind = plan.kind;
    c.label = plan.label;
    if (plan.kind == CaptureKind::kTurntable) {
      c.radius_m = plan.radius_m;  // as stated on the bench, not the true radius
      c.rpm = plan.rpm;
      c.up_axis = plan.up_axis;
    }
    const long n = std::lround(duration_s * rate_hz);
    c.samples.reserve(static_cast<std::size_t>(n));
    for (long k = 0; k < n; ++k) {
      const double t_s = SampleTimeS(start_s, k, rate_hz);
      c.samples.push_back(MeasurePerAxis(SpecificForcePerAxis(mounting, t_s), t_s));
    }
    captures.push_back(std::move(c));
    start_s += duration_s + scenario_.bench.gap_s;
  }
  return captures;
}

}  // namespace accelcal::sim
