// An independent bench of capture sets, written from the physics, to check accelcal honestly.
//
// It shares NO code with the project: only the C++ standard library and Eigen. Everything
// below is written from the equations (docs/model.md, "The model", the lab chapter's notation), not
// from the project's simulator or effect code, so a mistake in either shows as a disagreement.
//
// The sensor (the project's notation and signs):
//
//   raw = K a^a + b          a^p = T a^a          T = [[1, -a_yz,  a_zy],
//                                                      [0,  1,    -a_zx],
//                                                      [0,  0,     1   ]]
//   K = diag(kx, ky, kz) counts per m/s^2, b counts, a_ij rad.
//
// For a true specific force f in the platform frame, a^a = T^-1 f and, with every effect of
// Effects (each zero by default), per axis j and per sample at time t and temperature T_c:
//
//   u_j   = a^a_j                                 (m/s^2: docs/model.md table's u, "u = a^a")
//   raw_j = b_j + drift_j (t - t_ref) + tcb_j (T_c - T_ref) + [t >= t_jump] jump_j
//         + [turntable] vre_j
//         + (1 + tcs_j (T_c - T_ref)) (k_j u_j (1 + asym_j sgn(u_j)) + q_j u_j^2 + c3_j u_j^3
//                                      + [j = x] c_x u_y u_z)
//         + white noise (std noise_j counts), rounded to whole counts and clipped to the ADC.
//
// jump: the zero-g level steps once during the session (a knock, a connector settling), at
// t_jump, in the gap before the middle capture. vre: a constant shift of the zero-g level while
// the table turns (the motor's vibration rectified by the sensor). asym: the sensitivity differs
// for positive and negative inputs by +-asym_j. None of the three is in accelcal's library.
//
// t_ref and T_ref are the means over the captures of each capture's mean sample time and mean
// temperature (the project's reference points), so the nine-parameter truth (b, K, a_ij) is the
// sensor at the session's typical conditions.
//
// Units of the cubic and the cross-axis coupling: c3 in counts/(m/s^2)^3 and c_x in
// counts/(m/s^2)^2, both on u = a^a in m/s^2 (the same u as the library's quadratic q). So
// c3_x = 1e-4 adds 1e-4 * 23.54^3 = 1.30 counts = 38 mm/s^2 (k = 34.6) on x at 2.4 g, and
// c_x = 0.03 adds 0.03 * (g/sqrt(3))^2 = 0.96 counts = 28 mm/s^2 on x at the (1,1,1) corner.
// What a magnitude fit can see of the coupling: a^a_x grows by kappa_x u_y u_z with
// kappa_x = c_x / k_x (1/(m/s^2)), so |a| grows by kappa_x u_x u_y u_z / |u| to first order;
// the truth states kappa = c_x / k_x (the sum over the axes of such terms, one axis here). Of a
// tilt theta the magnitude sees 1 - cos(theta), stated as tilt_loss.
//
// The bench. Static pose: "up" (unit, sensor frame) is the specific force's direction,
// f = g up, turned by a small random placement error. Turntable: the table frame has X_t
// radially OUTWARD through the sensing point, Z_t up the spin axis, Y_t = Z_t x X_t; the sensor
// is mounted with its `radial` axis along X_t and its `up` axis along Z_t (the project's
// convention: turntable_stability.h, "sensor axes pointing radially outward and up the spin
// axis"; "+x radial" means +x points away from the spin axis). At constant rate w the only
// kinematic acceleration of a point at p_t is centripetal, a = -w^2 (p_x, p_y, 0), toward the
// axis; the accelerometer measures specific force f = a - g_vec = a + g up_world, so
//
//   f_t = -w^2 (p_x, p_y, 0) + g up_world(t)        (the radial axis reads -w^2 r: negative)
//
// with p_t = (r + dr, 0, 0) (+ the axis's own offset for the size effect) and w = (1 + s) w_stated.
// A spin axis tilted by theta from the vertical (about the world X axis) gives, in the table
// frame turned by phi(t) = phi0 + w t about its axis,
//   up_world(t) = (sin(theta) sin(phi), sin(theta) cos(phi), cos(theta)):
// gravity's in-plane part g sin(theta) swings once per revolution in the sensor frame. Samples
// are generated in time, so both the capture's mean and its scatter carry the tilt.
#pragma once

#include <cstdint>
#include <map>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace physgen {

struct Sensor {
  Eigen::Vector3d bias_counts{2051.3, 2039.6, 2062.8};
  Eigen::Vector3d scale_counts_per_mps2{34.62, 35.07, 34.41};
  double a_yz_rad = 0.0042;
  double a_zy_rad = -0.0031;
  double a_zx_rad = 0.0057;
  Eigen::Vector3d noise_counts{1.5, 1.5, 1.7};  // white noise, per-sample std, counts
  double rate_hz = 100.0;
  bool quantize = true;  // round to whole counts and clip to [adc_min, adc_max]
  double adc_min = 0.0;
  double adc_max = 4095.0;

  // T of the header comment.
  Eigen::Matrix3d Misalignment() const;
};

struct Effects {
  // Inside the project's library (names and units as its table in docs/model.md).
  Eigen::Vector3d quadratic = Eigen::Vector3d::Zero();    // q_j, counts/(m/s^2)^2
  Eigen::Vector3d temp_bias = Eigen::Vector3d::Zero();    // tc_bias_j, counts/degC
  Eigen::Vector3d temp_scale = Eigen::Vector3d::Zero();   // tc_scale_j, 1/degC
  Eigen::Vector3d drift = Eigen::Vector3d::Zero();        // drift_j, counts/s
  double radius_offset_m = 0.0;                           // dr: true radius = stated + dr
  double rpm_scale = 0.0;                                 // s: true speed = (1 + s) stated
  Eigen::Vector3d size_effect_m = Eigen::Vector3d::Zero();  // d_j: axis j's mass at d_j e_j
  // Outside the library.
  Eigen::Vector3d cubic = Eigen::Vector3d::Zero();  // c3_j, counts/(m/s^2)^3
  double cross_x_yz = 0.0;                          // c_x: raw_x += c_x u_y u_z, counts/(m/s^2)^2
  double tilt_rad = 0.0;                            // turntable spin axis from the vertical
  // Outside the library (also after issue 13 added the three above).
  Eigen::Vector3d asym_scale = Eigen::Vector3d::Zero();  // asym_j: k_j (1 +- asym_j) for u_j >< 0
  Eigen::Vector3d bias_jump = Eigen::Vector3d::Zero();   // jump_j counts, once, mid-session
  Eigen::Vector3d turntable_bias = Eigen::Vector3d::Zero();  // vre_j counts while turning
};

enum class Kind { kStatic, kTurntable };

struct CaptureSpec {
  Kind kind = Kind::kStatic;
  std::string label;
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  // static: "up" in the sensor frame (any length)
  double radius_m = 0.0;                          // turntable, as stated (the ruler)
  double rpm = 0.0;                               // turntable, as stated
  std::string radial_axis = "+x";                 // turntable: sensor axis radially outward
  std::string up_axis = "+z";                     // turntable: sensor axis up the spin axis
  double duration_s = 10.0;
};

struct Bench {
  double gravity_mps2 = 9.80665;
  double placement_error_deg = 0.5;  // std of each component of a small random rotation
  double first_start_s = 5.0;        // session clock at the first capture's first sample
  double gap_min_s = 15.0;           // time between captures (repositioning), uniform in
  double gap_max_s = 40.0;           //   [gap_min_s, gap_max_s]
  bool temperature = true;           // write temp_c (a warm-up over the session)
  double temp_start_c = 22.0;
  double temp_end_c = 28.0;
  double warmup_tau_s = 600.0;  // T(t) = end + (start - end) exp(-t / tau)
  double temp_noise_c = 0.02;   // the temperature sensor's own noise (written values only)
};

struct Sample {
  double t_s = 0.0;
  double temp_c = 0.0;  // as written (with the temperature sensor's noise)
  Eigen::Vector3d raw_counts = Eigen::Vector3d::Zero();
};

struct CaptureData {
  CaptureSpec spec;
  double start_s = 0.0;
  std::vector<Sample> samples;
  // For the self-checks: the capture's noise-free truth.
  Eigen::Matrix3d placement = Eigen::Matrix3d::Identity();  // P: platform = P^T (ideal)
  double phase0_rad = 0.0;                                  // turntable phase at start
};

struct CaptureSetData {
  Sensor sensor;
  Effects effects;
  Bench bench;
  double t_ref_s = 0.0;     // mean over captures of the mean sample time
  double temp_ref_c = 0.0;  // mean over captures of the mean true temperature
  double jump_t_s = 0.0;    // when the bias jump happens (mid-gap before the middle capture)
  std::vector<CaptureData> captures;
};

// Signed sensor axis "+x" ... "-z" as a unit vector; throws std::invalid_argument otherwise.
Eigen::Vector3d AxisVector(const std::string& axis);

// Platform -> table rotation M of a turntable mounting (v_table = M v_platform): rows are the
// radial axis, up x radial, and up.
Eigen::Matrix3d MountingRotation(const std::string& radial_axis, const std::string& up_axis);

// The true specific force (platform frame, m/s^2) that axis j's proof mass feels at time t in
// capture c (the offset of the size effect included; j = -1: the nominal sensing point).
Eigen::Vector3d SpecificForce(const CaptureSetData& set, const CaptureData& c, double t_s, int j);

// The true temperature of the sensor at session time t, degC.
double TrueTemperatureC(const Bench& bench, double t_s);

// The noise-free reading (counts, not rounded) at time t in capture c: the forward model of the
// header comment.
Eigen::Vector3d NoiseFreeReading(const CaptureSetData& set, const CaptureData& c, double t_s);

// Generates a set: times and temperatures first (so the references are known), then samples.
CaptureSetData Generate(const Sensor& sensor, const Effects& effects, const Bench& bench,
                        const std::vector<CaptureSpec>& plan, std::mt19937_64& rng);

// The project's capture-set CSV (docs/formats.md, "Capture-set file (CSV)").
void WriteCsv(const CaptureSetData& set, std::ostream& out);

// The truth: the nine parameters, the references, the injected effects (only the non-zero ones,
// in-library effects under the library's names and parameter names), as JSON.
void WriteTruthJson(const CaptureSetData& set, const std::map<std::string, std::string>& info,
                    std::ostream& out);

// The lab chapter's plan (procedures/full_calibration.toml): 6 faces, 3 tilted poses with
// independent sign patterns, the turntable at 0.05/0.10/0.15 m and 120 rpm with each axis radial.
std::vector<CaptureSpec> SeedPlan(double static_s, double turntable_s);
// A longer plan: 26 static directions (faces, edges, corners) and each signed axis radial at
// 3 radii x 120 rpm plus 0.10 m at 90 rpm and 0.15 m at 150 rpm (30 turntable runs).
std::vector<CaptureSpec> RichPlan(double static_s, double turntable_s);

// Draws a plausible sensor around the nominal one: bias +-20 counts, scale +-2 %,
// misalignment +-8 mrad (uniform).
Sensor DrawSensor(const Sensor& nominal, std::mt19937_64& rng);

}  // namespace physgen
