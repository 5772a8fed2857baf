// The capture planner: the fit's uncertainty predicted before a capture is taken, and the
// capture lengths that reach a target uncertainty in the least bench time.
//
// Prediction. The fit (calibration_fit.h) minimizes sum_i (r_i / sigma_i)^2 with the seed's
// residual r_i = |T K^-1 (mean_i - b)| - |f_i| (sensor_model.h: raw = K a^a + b, a^p = T a^a,
// T = [[1, -a_yz, a_zy], [0, 1, -a_zx], [0, 0, 1]]), sigma_i^2 = g_i^T Cov(mean_i) g_i with
// g_i = dr_i/d(mean raw), and Cov(mean_i) = Sigma / n_i: the per-sample covariance (floored at
// the quantization's 1/12 count^2 per axis, as the fit floors it) over the sample count. Its
// covariance is (J^T W J)^-1, J_ij = dr_i/dp_j, W = diag(1/sigma_i^2): the inverse of the
// Fisher information of the captures. Before capturing, the means are those the nominal sensor
// would read, mean_i = K T^-1 f_i + b, with f_i the planned specific force; n_i = rate * d_i. So
// the information is linear in the capture lengths d_i,
//     I(d) = sum_i d_i A_i,   A_i = rate J_i^T J_i / (g_i^T Sigma g_i),
// and the predicted type-A standard uncertainty of parameter j is sqrt((I(d)^-1)_jj). It holds
// for the fit's own noise-only covariance (chi2/dof near 1); the fit scales its sigmas by
// sqrt(chi2/dof) when the scatter is larger, so the planner aims under the target by a margin.
//
// The expanded uncertainty the certificate prints (uncertainty_budget.h) adds the type-B
// contributions of the reference quantities (gravity, radius, speed, tilt), which no capture
// length reduces: the planner takes them from the budget of the predicted fit, so a target below
// them is reported unreachable, never planned for.
//
// Planning. Bench time of a plan = sum over the captures taken of (handling + settling +
// capture length) + each turntable mounting used, once. For the captures kept, the lengths
// minimize the total capture time subject to u_A,j(d) <= the target's allowance for every
// targeted j, each d_i within [min_capture_s, max_capture_s]: a convex problem (the diagonal of
// the inverse of an affine matrix function is convex), solved by giving time, a small step at a
// time, to the capture that lowers the targets' shortfall most per second. Captures marked
// optional are then left out, one at a time, the one whose absence saves the most bench time
// first, while the rest still reach the target (and min_captures are kept): those "buy nothing"
// for this sensor.
//
// Units: counts (bias, noise), relative (scale: 1e-6 = 1 ppm), rad (misalignment), s, m/s^2.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"
#include "accelcal/base/sensor_model.h"
#include "accelcal/calibration/uncertainty_budget.h"

namespace accelcal {

// One capture of the procedure, before it is taken.
struct PlannedCapture {
  std::string id;                          // the procedure step's id
  CaptureKind kind = CaptureKind::kStatic;
  // The true specific force in the platform frame, m/s^2: a static pose g * up; a turntable run
  // -w^2 r along the radial axis (the radial axis points away from the spin axis) + g along up.
  Eigen::Vector3d specific_force_mps2 = Eigen::Vector3d::UnitZ();
  double radius_m = kNaN;                  // turntable, as stated
  double rpm = kNaN;                       // turntable, as stated
  double handling_s = 20.0;                // setting it up: a prism pose, a radius changed
  std::string mounting;                    // turntable mounting it needs ("" none): paid once
  double mounting_s = 0.0;                 // the mounting's own time, paid once per mounting
  double settle_s = 0.0;                   // waiting for stillness before the capture counts
  double min_capture_s = 1.0;              // whole revolutions on a turntable, at least
  double max_capture_s = 60.0;             // the procedure's
  bool optional = false;                   // may be left out when it buys nothing

  // The planned specific force of a static pose with "up" (any length, sensor frame), and of a
  // turntable run (radial and up signed axes).
  static Eigen::Vector3d StaticForce(const Eigen::Vector3d& up, double gravity_mps2);
  static Eigen::Vector3d TurntableForce(SensorAxis radial, SensorAxis up, double radius_m,
                                        double rpm, double gravity_mps2);
};

// The sensor as measured at the start of a session (the noise floor) and as nominally built.
struct PlannedSensor {
  SensorModel nominal;                               // scale, bias; misalignment 0 is fine
  Eigen::Vector3d noise_counts = Eigen::Vector3d::Ones();  // per-sample std, counts
  double rate_hz = 100.0;                            // samples per second
};

// The expanded uncertainty U (k = 2) to reach on every parameter of a kind; NaN: no target.
struct UncertaintyTarget {
  double bias_counts = kNaN;
  double scale_relative = kNaN;     // U of k_j / k_j (200e-6 = 200 ppm)
  double misalignment_rad = kNaN;

  bool Empty() const;
  // The target of parameter `index` (ParameterIndex) in its own unit (scale: counts per m/s^2,
  // from the relative target at `nominal`'s scale); NaN when none.
  double ForParameter(int index, const SensorModel& nominal) const;
};

struct PlanOptions {
  double gravity_mps2 = 9.80665;
  ReferenceUncertainties references;  // the procedure's equipment: type-B contributions
  double coverage_factor = 2.0;       // k of the target
  // Plan to this fraction of each target: the fit inflates its sigmas by sqrt(chi2/dof) when the
  // scatter happens to be large, and the certificate's budget adds the scatter-limited and
  // settling terms the planner does not predict, so a plan exactly at the target misses it.
  // Measured (bench/bench_time_bench.cpp, margin sweep: default sensor, references exact, 200
  // seeds of the physics bench, 2026-11-27): the U reached is 1.15-1.20 x the planned U; every
  // target met in 129/200 seeds at 0.85, 139 at 0.80, 149 at 0.75 (+24 s of capture, 818 s
  // against 774 s at the bench). 0.75 takes the mean reached U to 0.90 x the target.
  double margin = 0.75;
  int min_captures = 0;               // the procedure's limit: fewer is never planned
  double step_s = 0.5;                // the allocation's time step
  std::string Validate() const;
};

struct PlannedLength {
  std::string id;
  bool taken = true;        // false: left out (optional, buys nothing)
  double capture_s = 0.0;   // planned capture length
  long samples = 0;         // the sample count it means: what the stop rule counts to
};

struct PlannedParameter {
  int index = -1;
  double target_expanded = kNaN;   // U wanted, parameter's unit (NaN: none)
  double type_b = kNaN;            // the reference quantities' part of u_c, parameter's unit
  double predicted_a = kNaN;       // u_A predicted, parameter's unit
  double predicted_expanded = kNaN;  // U = k sqrt(u_A^2 + type_b^2)
  bool reachable = true;           // false: the type-B part alone exceeds the target
};

struct CapturePlan {
  bool feasible = false;            // every target met within each capture's maximum
  std::string message;              // why not, in words (empty when feasible)
  std::vector<PlannedLength> captures;        // in the input's order
  std::vector<PlannedParameter> parameters;   // the nine, ParameterIndex order
  double capture_s = 0.0;           // sum of planned capture lengths
  double settle_s = 0.0;
  double handling_s = 0.0;          // poses' handling and mountings
  double TotalS() const { return capture_s + settle_s + handling_s; }
  // Without the captures' maximum: the bench time the target would take (NaN: unreachable by
  // any length, a type-B part above it, or the captures do not determine the targets).
  double unbounded_total_s = kNaN;
  std::vector<std::string> buy_nothing;  // ids of optional captures left out
};

// The predicted covariance (the nine parameters, type A) of the fit of `captures` with capture
// lengths `lengths_s` (one per capture; 0 = not taken). An empty matrix when the captures do not
// determine the nine parameters.
Eigen::MatrixXd PredictCovariance(const std::vector<PlannedCapture>& captures,
                                  const std::vector<double>& lengths_s, const PlannedSensor& sensor,
                                  double gravity_mps2);

// The predicted budget per parameter for given lengths (type B from the budget of the predicted
// fit with the options' reference uncertainties).
std::vector<PlannedParameter> PredictUncertainty(const std::vector<PlannedCapture>& captures,
                                                 const std::vector<double>& lengths_s,
                                                 const PlannedSensor& sensor,
                                                 const UncertaintyTarget& target,
                                                 const PlanOptions& options);

// The plan of given lengths (a fixed plan: each capture as long as the procedure says; 0 = not
// taken): its times and predicted uncertainty; feasible when it meets `target`.
CapturePlan PlanOfLengths(const std::vector<PlannedCapture>& captures, const std::vector<double>& lengths_s,
                          const PlannedSensor& sensor, const UncertaintyTarget& target,
                          const PlanOptions& options);

// The plan reaching `target` in the least bench time (see the header).
CapturePlan PlanCaptures(const std::vector<PlannedCapture>& captures, const PlannedSensor& sensor,
                         const UncertaintyTarget& target, const PlanOptions& options);

}  // namespace accelcal
