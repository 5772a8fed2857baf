// The virtual bench: a simulated IMU accelerometer on a simulated bench (level table, prism,
// turntable), driven by a Scenario. Every test of the calibration stands on its physics:
//
//   specific force  f = a - gravity, gravity = [0, 0, -g] in the world frame (z up), so at rest
//                   f = [0, 0, +g] in the world frame.
//   static pose     the platform frame is turned so that world-up, expressed in platform
//                   coordinates, is the plan's `up`; then a small random placement rotation;
//                   then turned by the plan's yaw about the table's normal, and tilted with
//                   the table (bench.table_tilt_deg, as its feet leave it: AdjustTableFeet).
//   turntable       the table turns about its spin axis (world z, tilted by the turntable's
//                   tilt about world x: effects.turntable_tilt_rad until LevelTurntable) at w = rpm 2pi/60 (1 + rpm_scale). The sensing point is at
//                   (r + radius_offset) x_table; in the table frame
//                       f = -w^2 r_perp + R_world_to_table g z_world,
//                   so |f| = sqrt(g^2 + (w^2 r)^2) on a level table. radial_axis -> x_table,
//                   up_axis -> z_table, then the placement rotation.
//   measurement     a^a = T^-1 a^p (a^p = f in the platform frame), raw = K a^a + b, plus the
//                   effects (quadratic, temperature, drift), the long-term bias noise (random
//                   walk, instability: bias_noise.h), white noise, rounding to integer counts
//                   and clipping to the ADC range.
//
// Time: one session clock in s, starting at 0 with the first capture. Randomness: one
// std::mt19937_64 seeded from bench.seed, and a second one (seeded from bench.seed too) for the
// long-term bias noise, so that turning it on leaves the rest of the stream unchanged;
// SimulateCaptureSet and SimulateRecording reseed both, so each returns the same data for the
// same seed. The bias noise evolves with the session clock: across the gaps between captures
// too, and in whatever order of time the readings are asked for (a reading earlier than the
// previous one sees the bias unchanged).
#pragma once

#include <functional>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "accelcal/base/capture.h"
#include "accelcal/acquire/sim/scenario.h"

namespace accelcal::sim {

// A half-sine acceleration pulse, placed on the session clock and given its direction.
struct ActivePulse {
  double start_s = 0.0;                                       // session clock, s
  double duration_s = 0.1;                                    // s
  Eigen::Vector3d peak_world_mps2 = Eigen::Vector3d::Zero();  // peak acceleration, world frame
  // Acceleration of the pulse at session time t_s (zero outside it), world frame, m/s^2.
  Eigen::Vector3d AccelerationWorld(double t_s) const;
};

// How the sensor sits for one capture, placement error included: the true geometry.
struct Mounting {
  CaptureKind kind = CaptureKind::kStatic;
  double start_s = 0.0;  // session time the capture begins, s
  // Static: platform -> world rotation. Turntable: platform -> table rotation.
  Eigen::Matrix3d platform_rotation = Eigen::Matrix3d::Identity();
  double true_radius_m = 0.0;       // turntable: distance of the sensing point from the axis, m
  double omega_rad_per_s = 0.0;     // turntable: true table speed, rad/s
  double phase_rad = 0.0;           // turntable: table angle at start_s, rad
  double turntable_tilt_rad = 0.0;  // turntable: spin axis from vertical, about world x, rad
  std::vector<ActivePulse> pulses;  // bumps that fall in this capture
};

class VirtualBench {
 public:
  // Throws accelcal::Error when scenario.Validate() finds a problem.
  explicit VirtualBench(Scenario scenario);

  // Runs the whole plan: capture i starts gap_s after capture i-1 ends. Captures carry id i+1,
  // kind, label, the STATED radius and rpm, and samples on the session clock.
  std::vector<Capture> SimulateCaptureSet();

  // One continuous record of the plan's static poses turned by hand: the first pose held for
  // max(recording_quiet_start_s, its duration), each later pose held for its duration, and
  // moves of move_s between them (smooth slerp plus hand jitter). A bump's at_s counts from the
  // start of its pose's hold. Throws accelcal::Error when the plan has turntable captures.
  std::vector<Sample> SimulateRecording();
  // The same record in chunks of `chunk_samples` (the last may be shorter), handed to `sink` as
  // they are made: memory bounded by the chunk, whatever the record's length.
  using RecordingSink = std::function<void(const std::vector<Sample>& chunk)>;
  void SimulateRecording(const RecordingSink& sink, std::size_t chunk_samples = 4096);

  // --- Lower-level pieces, for a live sample source that drives the bench step by step. ---

  // Places the sensor for plan capture `plan_index` beginning at session time start_s: draws
  // the placement error (and the turntable's starting angle, and the bumps' directions).
  Mounting BeginCapture(int plan_index, double start_s);
  // Same for a plan entry that is not in the scenario (no bumps apply).
  Mounting BeginCapture(const CapturePlan& plan, double start_s);

  // Specific force at the nominal sensing point in the platform frame, m/s^2.
  Eigen::Vector3d SpecificForcePlatform(const Mounting& mounting, double t_s) const;
  // Column i: specific force in the platform frame at axis i's proof mass (size effect), m/s^2.
  Eigen::Matrix3d SpecificForcePerAxis(const Mounting& mounting, double t_s) const;

  // One reading of the sensor feeling `f_platform_mps2` at session time t_s: effects, noise,
  // quantization and clipping. Consumes random numbers.
  Sample Measure(const Eigen::Vector3d& f_platform_mps2, double t_s);
  // As above, with each axis feeling its own column of `f_per_axis_mps2`.
  Sample MeasurePerAxis(const Eigen::Matrix3d& f_per_axis_mps2, double t_s);
  // Noiseless, unquantized raw reading (effects included; no white or long-term bias noise),
  // counts.
  Eigen::Vector3d IdealRaw(const Eigen::Matrix3d& f_per_axis_mps2, double t_s) const;

  // The technician turns the table's feet: its tilt (bench.table_tilt_deg's convention) less
  // `correction_deg`. Placements from now on stand on the new table.
  void AdjustTableFeet(const Eigen::Vector2d& correction_deg);
  Eigen::Vector2d table_tilt_deg() const { return table_tilt_deg_; }
  // The turntable's spin-axis tilt times `keep` (a leveling that removes 1 - keep of it); the
  // next turntable mounting turns on the new axis.
  void LevelTurntable(double keep);
  double turntable_tilt_rad() const { return turntable_tilt_rad_; }

  // Sensor temperature at session time t_s, degC.
  double TemperatureC(double t_s) const;
  // Session length the temperature ramp spans, s (the plan's, or the recording's while one runs).
  double session_duration_s() const { return session_duration_s_; }

  // Restarts the random streams from `seed` (and the long-term bias noise from its start).
  void Reseed(std::uint64_t seed);

  // The true model and everything else the bench was built from.
  const Scenario& scenario() const { return scenario_; }

 private:
  Eigen::Matrix3d RandomPlacementRotation();
  Eigen::Vector3d PulseAccelerationWorld(const Mounting& mounting, double t_s) const;
  Eigen::Vector3d SpecificForceAt(const Mounting& mounting, double t_s,
                                  const Eigen::Vector3d& offset_platform_m) const;

  // The reading with its lagging share (EffectsSpec::settling_share): `ideal_counts` at `t_s`.
  Eigen::Vector3d Settle(const Eigen::Vector3d& ideal_counts, double t_s);

  Scenario scenario_;
  std::mt19937_64 rng_;
  BiasNoise bias_noise_;
  // The lagging part's state: what it reads now, and when it was last advanced (NaN: not yet).
  Eigen::Vector3d lagged_counts_ = Eigen::Vector3d::Zero();
  double lagged_t_s_ = kNaN;
  double session_duration_s_ = 0.0;
  Eigen::Vector2d table_tilt_deg_;  // as the feet are now
  double turntable_tilt_rad_;       // as the turntable stands now
};

// Time of sample k of a stream starting at start_s, s, on a 1 us grid (exact multiples print
// short and round-trip through text).
double SampleTimeS(double start_s, long k, double rate_hz);

// Rotation R with R * from = to for unit vectors (any valid one when they are opposite).
Eigen::Matrix3d RotationBetween(const Eigen::Vector3d& from, const Eigen::Vector3d& to);

}  // namespace accelcal::sim
