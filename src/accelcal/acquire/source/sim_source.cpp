#include "accelcal/acquire/source/sim_source.h"

#include <algorithm>
#include <cmath>

#include "accelcal/base/error.h"
#include "accelcal/acquire/source/wall_clock.h"

namespace accelcal {
namespace {

using source_detail::SleepS;
using source_detail::kMinPacedBurstS;
using source_detail::WallNowS;

constexpr int kTonesPerAxis = 3;
// Hand jitter while settling: each of 3 tones per axis, m/s^2 (RMS ~0.5 m/s^2 at its peak:
// clearly motion to a stability check, far below clipping).
constexpr double kJitterAmplitudeMps2 = 0.4;
// Share of settle_s spent turning into the new pose; the rest is the hand letting go.
constexpr double kTurnFraction = 0.6;
// Samples generated per Read at most (a caller that stalls catches up over several calls).
constexpr long kMaxSamplesPerRead = 200000;

double SmoothStep(double tau) { return tau * tau * tau * (10.0 - 15.0 * tau + 6.0 * tau * tau); }

sim::Scenario WithOptions(sim::Scenario scenario, const SimOptions& options) {
  if (std::string why = options.Validate(); !why.empty()) throw Error("sim: " + why);
  if (!std::isnan(options.placement_error_deg))
    scenario.bench.placement_error_deg = options.placement_error_deg;
  return scenario;
}

}  // namespace

SimSource::SimSource(sim::Scenario scenario, const SimOptions& options, double dead_after_s,
                     double gap_factor)
    : options_(options),
      bench_(WithOptions(std::move(scenario), options)),
      tracker_(gap_factor, dead_after_s, WallNowS()),
      // A stream apart from the bench's, so that settling and bumps do not shift its noise.
      rng_(bench_.scenario().bench.seed ^ 0x9e3779b97f4a7c15ULL),
      shake_rng_(bench_.scenario().bench.seed ^ 0x3c6ef372fe94f82bULL),
      technician_(bench_.scenario().technician),
      wall_origin_s_(WallNowS()) {
  sim::CapturePlan level;
  level.kind = CaptureKind::kStatic;
  level.up = Eigen::Vector3d::UnitZ();
  Place(level, false);
  ReadResult ignored;
  tracker_.OnLinkUp(WallNowS(), &ignored);
}

double SimSource::now_s() const {
  return sim::SampleTimeS(0.0, next_k_, bench_.scenario().sensor.rate_hz);
}

ReadResult SimSource::Read(double timeout_s, std::vector<Sample>* out) {
  ReadResult result;
  const double deadline_s = WallNowS() + std::max(0.0, timeout_s);
  const double rate_hz = bench_.scenario().sensor.rate_hz;
  for (;;) {
    const double wall_s = WallNowS();
    const long due = SamplesDue(wall_s);
    const double burst_due_s = last_burst_wall_s_ + kMinPacedBurstS;
    const bool burst_time = options_.speed == 0.0 || wall_s >= burst_due_s || wall_s >= deadline_s;
    if (due > 0 && burst_time) {
      const size_t first = out->size();
      for (long i = 0; i < due; ++i) out->push_back(Generate(next_k_++));
      tracker_.OnSamples(out->data() + first, due, wall_s, &result);
      last_burst_wall_s_ = wall_s;
      break;
    }
    if (wall_s >= deadline_s) break;
    const double next_due_s =
        wall_origin_s_ + static_cast<double>(next_k_) / rate_hz / options_.speed;
    SleepS(std::min(deadline_s, std::max(next_due_s, burst_due_s)) - wall_s);
  }
  tracker_.Tick(WallNowS(), &result);
  return result;
}

long SimSource::SamplesDue(double wall_now_s) const {
  const double rate_hz = bench_.scenario().sensor.rate_hz;
  if (options_.speed == 0.0)
    return std::max(1L, std::lround(options_.fast_chunk_s * rate_hz));
  // Sample k (t = k / rate) is due once the simulated clock reaches its t.
  const double sim_s = (wall_now_s - wall_origin_s_) * options_.speed;
  const long due = static_cast<long>(std::floor(sim_s * rate_hz)) + 1 - next_k_;
  return std::clamp(due, 0L, kMaxSamplesPerRead);
}

void SimSource::PlaceStatic(const Eigen::Vector3d& up_platform, double yaw_rad) {
  if (!up_platform.allFinite() || up_platform.norm() == 0.0 || !std::isfinite(yaw_rad))
    throw Error("sim: a static pose needs a non-zero, finite up direction");
  sim::CapturePlan plan;
  plan.kind = CaptureKind::kStatic;
  plan.up = up_platform.normalized();
  plan.yaw_rad = yaw_rad;
  PlaceAsked(plan);
}

void SimSource::PlaceTurntable(double radius_m, double rpm, sim::SensorAxis radial,
                               sim::SensorAxis up) {
  if (!(radius_m > 0.0) || !(rpm > 0.0) || !std::isfinite(radius_m) || !std::isfinite(rpm))
    throw Error("sim: a turntable mounting needs a positive radius and speed");
  if (sim::SensorAxisVector(radial).dot(sim::SensorAxisVector(up)) != 0.0)
    throw Error("sim: the radial axis must be perpendicular to the up axis");
  sim::CapturePlan plan;
  plan.kind = CaptureKind::kTurntable;
  plan.radius_m = radius_m;
  plan.rpm = rpm;
  plan.radial_axis = radial;
  plan.up_axis = up;
  PlaceAsked(plan);
}

void SimSource::PlaceAsked(const sim::CapturePlan& asked) {
  const sim::Deed deed = technician_.Place(asked);
  Place(deed.placed, true);
  if (std::isfinite(deed.bump_at_s))
    ScheduleBump(settle_end_s_ + deed.bump_at_s, deed.bump_peak_mps2, deed.bump_duration_s);
}

void SimSource::StopTurntable() {
  if (mounting_.kind != CaptureKind::kTurntable) return;
  // The table stops with the sensor on it, seated as it was mounted: not a request to the
  // technician. The stop shakes it like a hand letting go.
  ++placements_;  // a fixture's loose board settles anew at a stop too
  mounting_ = bench_.StopTurntable(mounting_, now_s());
  turn_from_ = Eigen::Quaterniond(mounting_.platform_rotation);
  ScheduleSettle(true);
  MaybeScheduleBump();
}

void SimSource::AdjustTableFeet(const Eigen::Vector2d& tilt_deg) {
  if (!tilt_deg.allFinite()) return;
  bench_.AdjustTableFeet(technician_.spec().leveling_gain * tilt_deg);
}

void SimSource::LevelTurntable() { bench_.LevelTurntable(1.0 - technician_.spec().leveling_gain); }

void SimSource::Place(const sim::CapturePlan& plan, bool settle) {
  const double t_s = now_s();
  ++placements_;
  const bool was_static = mounting_.kind == CaptureKind::kStatic;
  const Eigen::Quaterniond before(PlatformToWorld(t_s));
  mounting_ = bench_.BeginCapture(plan, t_s);
  // Turn from where the sensor was only between static poses; a turntable is mounted by hand.
  const bool turn = settle && was_static && plan.kind == CaptureKind::kStatic;
  turn_from_ = turn ? before : Eigen::Quaterniond(mounting_.platform_rotation);
  ScheduleSettle(settle);
  if (settle) MaybeScheduleBump();
}

void SimSource::ScheduleSettle(bool settle) {
  settle_start_s_ = now_s();
  settle_end_s_ = settle_start_s_ + (settle ? options_.settle_s : 0.0);
  std::uniform_real_distribution<double> frequency_hz(0.8, 3.0);
  std::uniform_real_distribution<double> phase_rad(0.0, 2.0 * M_PI);
  tones_.clear();
  for (int i = 0; i < 3 * kTonesPerAxis; ++i)
    tones_.push_back({kJitterAmplitudeMps2, frequency_hz(rng_), phase_rad(rng_)});
}

// A knock on the bench a little after the sensor has settled: a short horizontal pulse.
void SimSource::MaybeScheduleBump() {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  if (!(unit(rng_) < options_.bump_probability)) return;
  const double heading_rad = 2.0 * M_PI * unit(rng_);
  const double peak_mps2 = 2.0 + 3.0 * unit(rng_);
  sim::ActivePulse pulse;
  pulse.start_s = settle_end_s_ + 1.0 + 3.0 * unit(rng_);
  pulse.duration_s = 0.05 + 0.15 * unit(rng_);
  pulse.peak_world_mps2 = peak_mps2 * Eigen::Vector3d(std::cos(heading_rad), std::sin(heading_rad), 0.0);
  mounting_.pulses.push_back(pulse);
  ++bumps_scheduled_;
}

// A knock the scenario asks for: its heading from the shaking stream (the operator's stream
// stays as it would be without it).
void SimSource::ScheduleBump(double at_s, double peak_mps2, double duration_s) {
  const double heading_rad = std::uniform_real_distribution<double>(0.0, 2.0 * M_PI)(shake_rng_);
  sim::ActivePulse pulse;
  pulse.start_s = at_s;
  pulse.duration_s = duration_s;
  pulse.peak_world_mps2 = peak_mps2 * Eigen::Vector3d(std::cos(heading_rad), std::sin(heading_rad), 0.0);
  mounting_.pulses.push_back(pulse);
  ++bumps_scheduled_;
}

Eigen::Vector3d SimSource::JitterWorld(double t_s) const {
  if (t_s < settle_start_s_ || t_s >= settle_end_s_) return Eigen::Vector3d::Zero();
  const double tau = (t_s - settle_start_s_) / (settle_end_s_ - settle_start_s_);
  const double envelope = std::sin(M_PI * tau);
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3 * kTonesPerAxis; ++i) {
    const JitterTone& tone = tones_[static_cast<size_t>(i)];
    a(i / kTonesPerAxis) +=
        tone.amplitude_mps2 * std::sin(2.0 * M_PI * tone.frequency_hz * t_s + tone.phase_rad);
  }
  return envelope * a;
}

Eigen::Matrix3d SimSource::PlatformToWorld(double t_s) const {
  const Eigen::Quaterniond to(mounting_.platform_rotation);
  const double turn_s = kTurnFraction * (settle_end_s_ - settle_start_s_);
  if (turn_s <= 0.0 || t_s >= settle_start_s_ + turn_s) return to.toRotationMatrix();
  const double tau = std::clamp((t_s - settle_start_s_) / turn_s, 0.0, 1.0);
  return turn_from_.slerp(SmoothStep(tau), to).toRotationMatrix();
}

Eigen::Vector3d SimSource::ShakeWorld(double t_s) {
  const double rms = technician_.ShakeRmsAt(t_s);
  if (!(rms > 0.0)) return Eigen::Vector3d::Zero();
  std::normal_distribution<double> unit;
  return rms * Eigen::Vector3d(unit(shake_rng_), unit(shake_rng_), unit(shake_rng_));
}

Sample SimSource::Generate(long k) {
  const double t_s = sim::SampleTimeS(0.0, k, bench_.scenario().sensor.rate_hz);
  if (mounting_.kind == CaptureKind::kTurntable) {
    // The table's own kinematics (and bumps) come from the bench; the hand's shake while the
    // mounting settles and the bench's shaking are added on top, roughly (their frame matters
    // little).
    Eigen::Matrix3d f_mps2 = bench_.SpecificForcePerAxis(mounting_, t_s);
    f_mps2.colwise() += JitterWorld(t_s) + ShakeWorld(t_s);
    if (force_tap_) force_tap_(t_s, f_mps2);
    return bench_.MeasurePerAxis(f_mps2, t_s);
  }
  Eigen::Vector3d f_world = bench_.scenario().bench.gravity_mps2 * Eigen::Vector3d::UnitZ() +
                            JitterWorld(t_s) + ShakeWorld(t_s);
  for (const sim::ActivePulse& pulse : mounting_.pulses) f_world += pulse.AccelerationWorld(t_s);
  const Eigen::Vector3d f_platform = PlatformToWorld(t_s).transpose() * f_world;
  if (force_tap_) force_tap_(t_s, f_platform.replicate<1, 3>());
  return bench_.Measure(f_platform, t_s);
}

}  // namespace accelcal
