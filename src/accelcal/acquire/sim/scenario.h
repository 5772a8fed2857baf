// A virtual-bench scenario: the true sensor, its ADC, the bench, optional non-ideal effects and
// the plan of captures. Read from TOML (scenarios/*.toml documents every field) or built in code.
//
// Units: SI everywhere (m/s^2, m, s, rad, degC) except where a name says otherwise: counts for
// ADC readings, rpm for the turntable speed as typed on the bench, deg for placement error.
//
// Frames (the virtual bench's conventions, used by VirtualBench):
//   world     z up; gravity is [0, 0, -g], so at rest the specific force is [0, 0, +g].
//   platform  the sensor's orthonormal frame of sensor_model.h (x^p along x^a, ...).
//   table     turntable frame: z along the spin axis (up), x radially outward through the sensor.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"
#include "accelcal/base/capture_set.h"
#include "accelcal/base/sensor_model.h"
#include "accelcal/acquire/sim/bench_fixture.h"
#include "accelcal/acquire/sim/bias_noise.h"

namespace accelcal::sim {

// Signed sensor axes ("+x" ... "-z") live in capture.h; the bench uses the same names.
using accelcal::SensorAxis;
using accelcal::SensorAxisToString;
using accelcal::StringToSensorAxis;
using accelcal::SensorAxisVector;

// [sensor]: the true parameters the calibration should recover, plus noise and rate.
struct SensorSpec {
  SensorModel model;                                       // bias, scale, misalignment (truth)
  Eigen::Vector3d noise_counts = Eigen::Vector3d::Zero();  // white-noise std per axis, counts
  double rate_hz = 100.0;                                  // output data rate, samples per s
  // Long-term bias noise (bias random walk K, counts/sqrt(s); bias instability B, counts, with
  // the correlation-time range of its Gauss-Markov approximation): bias_noise.h. Off by default.
  BiasNoiseSpec bias_noise;
};

// [adc]: readings are rounded to integer counts and clipped to the converter's range.
struct AdcSpec {
  int bits = 12;           // resolution, bits (1..32)
  bool is_signed = false;  // TOML `signed`: range -2^(bits-1)..2^(bits-1)-1, else 0..2^bits-1

  double MinCounts() const;
  double MaxCounts() const;
  AdcRange Range() const { return {MinCounts(), MaxCounts()}; }
};

// [bench]: the simulated bench and the person operating it.
struct BenchSpec {
  double gravity_mps2 = 9.80665;     // local gravity, m/s^2
  std::uint64_t seed = 1;            // random seed; same seed => identical output
  double placement_error_deg = 0.5;  // std of each component of a random small rotation
                                     // applied to every pose and mounting, deg
  double gap_s = 20.0;               // time between captures (repositioning), s
  double capture_duration_s = 10.0;  // default capture length, s
  double temperature_c = 25.0;       // ambient; also the reference of temperature effects, degC
  double recording_quiet_start_s = 30.0;  // continuous recording: first pose held this long, s
  double move_s = 4.0;                    // continuous recording: time to turn between poses, s
  // The table the prism stands on, as its feet leave it: [about x, about y], deg, in the
  // leveling convention (app/wizard/leveling.h): about x positive = the +y side low; about y
  // positive = the +x side low. Static poses stand on it; the technician adjusts the feet
  // when the wizard's leveling says so (Technician::leveling_gain).
  Eigen::Vector2d table_tilt_deg = Eigen::Vector2d::Zero();
};

// Temperature of the sensor over the session, degC: from start_c at t = 0 towards end_c.
// With warmup_tau_s = 0 a linear ramp that reaches end_c at the end of the session; with
// warmup_tau_s > 0 the exponential approach of a part warming up after power-on,
// start + (end - start)(1 - exp(-t / tau)): not linear in time, so a temperature effect can be
// told apart from a drift in time.
struct TemperatureRamp {
  double start_c = 25.0;
  double end_c = 25.0;
  double warmup_tau_s = 0.0;
};

// [[effects.bump]]: a half-sine acceleration pulse in a random horizontal direction.
struct Bump {
  int capture = 0;          // 0-based index into the plan
  double at_s = 0.0;        // start, seconds into the capture
  double peak_mps2 = 0.0;   // peak acceleration, m/s^2
  double duration_s = 0.1;  // pulse length, s
};

// [effects]: non-ideal behaviour the nine-parameter model does not describe. All off by default.
struct EffectsSpec {
  // raw_i += q_i (a^a_i)^2, counts per (m/s^2)^2.
  Eigen::Vector3d quadratic_counts_per_mps2_sq = Eigen::Vector3d::Zero();
  // bias_i += c_i (temp - bench temperature), counts per degC.
  Eigen::Vector3d bias_temp_coeff_counts_per_c = Eigen::Vector3d::Zero();
  // scale_i *= 1 + c_i (temp - bench temperature), relative, per degC.
  Eigen::Vector3d scale_temp_coeff_per_c = Eigen::Vector3d::Zero();
  // Sensor temperature; absent => constant at the bench temperature.
  std::optional<TemperatureRamp> temperature;
  // bias_i += d_i t (t on the session clock), counts per s.
  Eigen::Vector3d bias_drift_counts_per_s = Eigen::Vector3d::Zero();
  // True sensing point is this much further out than the stated radius, m.
  double radius_offset_m = 0.0;
  // True table speed = stated rpm * (1 + rpm_scale), dimensionless.
  double rpm_scale = 0.0;
  // Offset of each axis's proof mass along its own axis from the nominal sensing point, sensor
  // frame, m: each axis feels the centripetal acceleration at its own position.
  Eigen::Vector3d size_effect_m = Eigen::Vector3d::Zero();
  // Spin axis tilted from vertical, rad: gravity turns once per revolution in the table frame.
  double turntable_tilt_rad = 0.0;
  // Settling after a change of pose (the package's anelastic after-effect, the mount's creep):
  // this share of each axis' reading lags what it should read, relaxing toward it with the time
  // constant settling_tau_s (first order), so a capture started soon after a change of pose
  // still carries part of the previous pose. 0 (the default): none; each share in [0, 1).
  Eigen::Vector3d settling_share = Eigen::Vector3d::Zero();
  double settling_tau_s = 15.0;  // s; > 0
  std::vector<Bump> bumps;
};

// One [[capture]] of the plan.
struct CapturePlan {
  CaptureKind kind = CaptureKind::kStatic;
  std::string label;
  // Static: direction of "up" (the specific force at rest) in the platform frame; only its
  // direction matters (ParseScenario normalizes it).
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  // Turntable: stated radius (m) and speed (rpm), and which sensor axes point radially outward
  // and up (perpendicular to each other).
  double radius_m = kNaN;
  double rpm = kNaN;
  SensorAxis radial_axis = SensorAxis::kPlusX;
  SensorAxis up_axis = SensorAxis::kPlusZ;
  // Capture length, s; NaN => the bench's capture_duration_s.
  double duration_s = kNaN;
  // Static: turned this much about the vertical on the table (the leveling reversal), rad.
  // Not read from files.
  double yaw_rad = 0.0;
};

// [[technician.shake]]: the bench shakes (a machine nearby, a hand resting on the table) over a
// stretch of the live bench's clock: white acceleration of rms_mps2 on each world axis.
struct Shake {
  double from_s = 0.0;    // sim clock, s
  double to_s = 0.0;      // s; > from_s
  double rms_mps2 = 0.0;  // per axis, m/s^2
};

// [[technician.mistake]]: when the wizard asks for a pose or a mounting, the technician does
// something else, `times` times after `after` correct placements of that request. A request is
// a static pose (asked_up) or a turntable mounting (asked_radial and asked_up_axis, and
// asked_radius_m when only one radius is meant). The deed: another face (up), another mounting
// (radial, up_axis), another radius (radius_m), and/or a knock on the bench bump_at_s after
// the sensor settles. What is absent is done as asked.
struct Mistake {
  std::optional<Eigen::Vector3d> asked_up;  // static request (normalized)
  std::optional<SensorAxis> asked_radial;   // turntable request
  std::optional<SensorAxis> asked_up_axis;
  double asked_radius_m = kNaN;             // NaN: any radius
  int after = 0;  // matching placements done right first
  int times = 1;  // placements that go wrong, then the technician gets it right
  std::optional<Eigen::Vector3d> up;        // static: the face put up instead (normalized)
  std::optional<SensorAxis> radial;         // turntable: mounted with this axis outward ...
  std::optional<SensorAxis> up_axis;        // ... and this one up
  double radius_m = kNaN;                   // turntable: mounted at this radius, m
  double bump_at_s = kNaN;                  // a knock this long after settling, s; NaN: none
  double bump_peak_mps2 = 3.0;              // its peak, m/s^2 (horizontal)
  double bump_duration_s = 0.1;             // its length, s

  bool static_request() const { return asked_up.has_value(); }
};

// [technician]: the person at the live virtual bench the wizard drives (SimSource). Only the
// live bench plays it; SimulateCaptureSet and SimulateRecording do not.
struct Technician {
  // Share of the advised correction made each time the feet are adjusted (the table after the
  // wizard's leveling advice, the turntable after a refusal for its tilt); (0, 1].
  double leveling_gain = 0.8;
  std::vector<Shake> shakes;
  std::vector<Mistake> mistakes;
};

// [lab]: what the virtual bench's lab owns and knows, offered at the wizard's welcome when the
// source is the virtual bench (ui/cli/wizard.cpp), so that a session taking every default is
// what a good lab would do (issue 27). Absent: this good lab. A scenario whose fault is the
// lab's (it does not know its gravity) states it.
struct LabSpec {
  // The welcome's gravity answer: "measured" is the bench's own gravity_mps2 as the lab measured
  // it, with `gravity_sigma_mps2`; anything else is offered as typed ("standard", "lat 45").
  std::string gravity = "measured";
  double gravity_sigma_mps2 = 2e-5;  // a measured gravity's standard uncertainty, m/s^2
  // The welcome's equipment answer (app/wizard/equipment_input.h): the items as the lab has
  // them, each identified, the radius read to 0.03 mm and the speed checked to 0.02 % with
  // calibrated instruments; "keep" keeps the procedure's (its example identifications).
  std::string equipment =
      "ruler id SIM-RUL-01 u 0.03 cal SIM-CAL-2025-017; turntable id SIM-TT-01 u 0.02 cal "
      "SIM-CAL-2025-018; level id SIM-LVL-01; prism id SIM-PR-01";

  // The welcome's gravity answer for a bench of `bench_gravity_mps2`.
  std::string GravityAnswer(double bench_gravity_mps2) const;
};

struct Scenario {
  std::string source_name;  // file the scenario came from, for messages ("<default>" in code)
  SensorSpec sensor;
  AdcSpec adc;
  BenchSpec bench;
  EffectsSpec effects;
  Technician technician;
  LabSpec lab;
  std::vector<CapturePlan> captures;
  // [fixture]: several boards on one plate (bench_fixture.h); absent: the one [sensor].
  std::optional<BenchFixture> fixture;

  // Length of capture `index` of the plan, s.
  double CaptureDurationS(int index) const;
  // Session length of SimulateCaptureSet: every capture plus the gaps between them, s.
  double SessionDurationS() const;
  // Empty when the scenario can be simulated; otherwise the first problem found.
  std::string Validate() const;
};


// The shipped scenarios/bench_default.toml, in code: a 12-bit MMA7260Q-like part at +-6 g,
// 9 static poses and 9 turntable captures (3 mountings x 3 radii at 120 rpm), no effects.
Scenario DefaultScenario();

}  // namespace accelcal::sim
