#include "accelcal/acquire/capture_engine/turntable_stability.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

constexpr double kDegreesPerRadian = 180.0 / M_PI;
constexpr char kAxisLetters[3] = {'x', 'y', 'z'};
// Above this an entered radius is more likely a unit slip than a bench turntable, m.
constexpr double kLargestLikelyRadiusM = 2.0;

// The specific force of each finite sample (platform frame, m/s^2) and its time.
struct ForceSeries {
  std::vector<double> t_s;
  std::vector<Eigen::Vector3d> f_mps2;
};

ForceSeries ToForces(const std::vector<Sample>& samples, const SensorModel& model) {
  ForceSeries series;
  series.t_s.reserve(samples.size());
  series.f_mps2.reserve(samples.size());
  for (const Sample& s : samples) {
    if (!IsFinite(s)) continue;
    series.t_s.push_back(s.t_s);
    series.f_mps2.push_back(model.Calibrate(s.raw_counts));
  }
  return series;
}

// Least squares y = c0 + a cos(w tau) + b sin(w tau), tau = t - t_first: returns (c0, a, b).
Eigen::Vector3d FitOncePerRevolution(const std::vector<double>& t_s,
                                     const std::vector<double>& y, double w_rad_per_s) {
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < y.size(); ++k) {
    const double phase = w_rad_per_s * (t_s[k] - t_s.front());
    const Eigen::Vector3d row(1.0, std::cos(phase), std::sin(phase));
    normal += row * row.transpose();
    rhs += row * y[k];
  }
  return normal.ldlt().solve(rhs);
}

// Least squares of each axis's counts on 1, cos, sin at w (times from the first sample).
OncePerRevolution FitSwing(const std::vector<Sample>& samples, double w_rad_per_s) {
  OncePerRevolution swing;
  swing.t0_s = samples.front().t_s;
  swing.w_rad_per_s = w_rad_per_s;
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d rhs = Eigen::Matrix3d::Zero();  // column j: axis j
  for (const Sample& s : samples) {
    if (!IsFinite(s)) continue;
    const double phase = w_rad_per_s * (s.t_s - swing.t0_s);
    const Eigen::Vector3d row(1.0, std::cos(phase), std::sin(phase));
    normal += row * row.transpose();
    rhs += row * s.raw_counts.transpose();
  }
  const Eigen::Matrix3d coefficients = normal.ldlt().solve(rhs);
  swing.cos_counts = coefficients.row(1).transpose();
  swing.sin_counts = coefficients.row(2).transpose();
  return swing;
}

// "+x" ... "-z" for an axis-aligned unit vector; the vector itself otherwise.
std::string VectorAxisName(const Eigen::Vector3d& v) {
  const Eigen::Vector3d u = v.normalized();
  for (int i = 0; i < 3; ++i)
    if (std::abs(std::abs(u[i]) - 1.0) < 1e-9) return fmt::format("{}{}", u[i] > 0 ? '+' : '-', "xyz"[i]);
  return fmt::format("({:.2f}, {:.2f}, {:.2f})", u.x(), u.y(), u.z());
}

constexpr SensorAxis kAxes[6] = {SensorAxis::kPlusX, SensorAxis::kMinusX, SensorAxis::kPlusY,
                                 SensorAxis::kMinusY, SensorAxis::kPlusZ, SensorAxis::kMinusZ};

std::string MountingName(SensorAxis radial, SensorAxis up) {
  return fmt::format("{} radial, {} up", SensorAxisToString(radial), SensorAxisToString(up));
}

// How far the mean force is from -c radial + g up with c fitted (not negative), m/s^2.
double MountingResidual(const Eigen::Vector3d& mean, const Eigen::Vector3d& radial,
                        const Eigen::Vector3d& up, double g, double* c_fit) {
  *c_fit = std::max(0.0, -mean.dot(radial));
  return (mean - (-*c_fit * radial + g * up)).norm();
}

// Check 0: the mounting asked for against every perpendicular pair of signed axes.
void CheckMounting(const Eigen::Vector3d& mean, const TurntableSetup& setup,
                   const TurntableStabilityOptions& options, TurntableVerdict* v,
                   std::string* reason) {
  double c_asked = 0.0;
  const double asked = MountingResidual(mean, setup.radial_axis.normalized(),
                                        setup.up_axis.normalized(), options.gravity_mps2, &c_asked);
  double best = asked, c_best = c_asked;
  SensorAxis best_radial = kAxes[0], best_up = kAxes[0];
  bool other_better = false;
  for (SensorAxis r : kAxes) {
    for (SensorAxis u : kAxes) {
      const Eigen::Vector3d er = SensorAxisVector(r), eu = SensorAxisVector(u);
      if (std::abs(er.dot(eu)) > 0.5) continue;
      double c = 0.0;
      const double residual = MountingResidual(mean, er, eu, options.gravity_mps2, &c);
      if (residual < best - 1e-9) {
        best = residual, c_best = c, best_radial = r, best_up = u;
        other_better = true;
      }
    }
  }
  const double margin = std::max(options.min_mounting_residual_mps2, 0.1 * mean.norm());
  v->mounted_as_asked = !other_better || asked <= margin;
  if (v->mounted_as_asked) return;
  v->mounting_found = MountingName(best_radial, best_up);
  const char axis = "xyz"[static_cast<int>(best_radial) / 2];
  const std::string radial = VectorAxisName(setup.radial_axis), up = VectorAxisName(setup.up_axis);
  *reason = fmt::format(
      "wrong mounting: the samples show {} (the centripetal {:.3g} m/s^2 is on {}), not {} radial, "
      "{} up: mount the sensor with {} pointing away from the spin axis and {} up",
      v->mounting_found, c_best, axis, radial, up, radial, up);
}

std::string UnitSlipHint(double ratio, double radius_m, double tolerance) {
  for (const double factor : {10.0, 100.0, 1000.0}) {
    if (std::fabs(ratio * factor - 1.0) <= tolerance) {
      return fmt::format("radius looks {:g}x too large: {:.3g} m entered; did you mean {:.3g} m?",
                         factor, radius_m, radius_m / factor);
    }
    if (std::fabs(ratio / factor - 1.0) <= tolerance) {
      return fmt::format("radius looks {:g}x too small: {:.3g} m entered; did you mean {:.3g} m?",
                         factor, radius_m, radius_m * factor);
    }
  }
  return {};
}

std::string MismatchReason(const TurntableVerdict& v, const TurntableSetup& setup,
                           double tolerance) {
  if (std::string hint = UnitSlipHint(v.centripetal_ratio, setup.radius_m, tolerance);
      !hint.empty()) {
    return hint;
  }
  return fmt::format(
      "centripetal {:.3g} m/s^2 expected from {:.4g} rpm at {:.3g} m, {:.3g} measured: check rpm "
      "and radius (the measurement fits {:.4g} rpm at {:.3g} m, or {:.3g} m at {:.4g} rpm)",
      v.expected_centripetal_mps2, setup.rpm, setup.radius_m, v.measured_centripetal_mps2,
      setup.rpm * std::sqrt(std::max(v.centripetal_ratio, 0.0)), setup.radius_m,
      setup.radius_m * v.centripetal_ratio, setup.rpm);
}

Eigen::Vector3d MeanForce(const ForceSeries& series) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& f : series.f_mps2) mean += f;
  return mean / static_cast<double>(series.f_mps2.size());
}

// Check 1: the horizontal part of the mean force against w^2 r.
void CheckConsistent(const ForceSeries& series, const TurntableSetup& setup,
                     const TurntableStabilityOptions& options, TurntableVerdict* v) {
  const Eigen::Vector3d mean = MeanForce(series);
  const Eigen::Vector3d up = setup.up_axis.normalized();
  v->mean_magnitude_mps2 = mean.norm();
  v->measured_centripetal_mps2 = (mean - mean.dot(up) * up).norm();
  v->centripetal_ratio = v->measured_centripetal_mps2 / v->expected_centripetal_mps2;
  v->consistent = std::fabs(v->centripetal_ratio - 1.0) <= options.centripetal_tolerance;
}

// Check 2: the radial force's once-per-revolution sine, then the sub-window means without it.
void CheckSteady(const ForceSeries& series, const TurntableSetup& setup,
                         const TurntableStabilityOptions& options, TurntableVerdict* v) {
  const Eigen::Vector3d radial = setup.radial_axis.normalized();
  std::vector<double> radial_mps2(series.f_mps2.size());
  for (size_t k = 0; k < radial_mps2.size(); ++k) radial_mps2[k] = series.f_mps2[k].dot(radial);
  const double w = RpmToRadPerS(setup.rpm);
  const double span_s = series.t_s.back() - series.t_s.front();
  Eigen::Vector3d sine = Eigen::Vector3d::Zero();
  // Under one revolution the sine cannot be told from a trend: leave the wobble unmeasured.
  if (w * span_s >= 2.0 * M_PI) sine = FitOncePerRevolution(series.t_s, radial_mps2, w);

  const int parts = options.sub_windows;
  std::vector<double> sum(static_cast<size_t>(parts), 0.0);
  std::vector<long> count(static_cast<size_t>(parts), 0);
  for (size_t k = 0; k < radial_mps2.size(); ++k) {
    const double tau = series.t_s[k] - series.t_s.front();
    const int part = std::min(parts - 1, static_cast<int>(tau / span_s * parts));
    const double wobble = sine[1] * std::cos(w * tau) + sine[2] * std::sin(w * tau);
    sum[static_cast<size_t>(part)] += radial_mps2[k] - wobble;
    ++count[static_cast<size_t>(part)];
  }
  for (int p = 0; p < parts; ++p) {
    if (count[static_cast<size_t>(p)] == 0) continue;
    // The radial force points inward (-w^2 r along the outward axis).
    v->sub_window_centripetal_mps2.push_back(-sum[static_cast<size_t>(p)] /
                                             static_cast<double>(count[static_cast<size_t>(p)]));
  }
  const auto [lo, hi] = std::minmax_element(v->sub_window_centripetal_mps2.begin(),
                                            v->sub_window_centripetal_mps2.end());
  const double spread = *hi - *lo;
  v->speed_spread_fraction = spread / v->expected_centripetal_mps2;
  v->steady = spread <= std::max(options.speed_tolerance * v->expected_centripetal_mps2,
                                 options.min_speed_spread_mps2);
}

std::string UnsteadyReason(const TurntableVerdict& v, const TurntableStabilityOptions& options) {
  const double first = v.sub_window_centripetal_mps2.front();
  const double last = v.sub_window_centripetal_mps2.back();
  return fmt::format(
      "speed not steady: centripetal went from {:.3g} to {:.3g} m/s^2 across the window (spread "
      "{:.1f} %), limit {:.3g} %", first, last, 100.0 * v.speed_spread_fraction,
      100.0 * options.speed_tolerance);
}

// Check 3: the swing on every axis, its amplitude in m/s^2 through the rough scale.
void CheckLevel(const std::vector<Sample>& samples, const SensorModel& rough_model,
                const TurntableSetup& setup, const TurntableStabilityOptions& options,
                TurntableVerdict* v) {
  const double w = RpmToRadPerS(setup.rpm);
  std::vector<Sample> finite;
  for (const Sample& s : samples)
    if (IsFinite(s)) finite.push_back(s);
  const double span_s = finite.back().t_s - finite.front().t_s;
  if (w * span_s >= 2.0 * M_PI) {
    v->swing = FitSwing(finite, w);
    const Eigen::Vector3d cos_mps2 = v->swing.cos_counts.cwiseQuotient(rough_model.scale_counts_per_mps2);
    const Eigen::Vector3d sin_mps2 = v->swing.sin_counts.cwiseQuotient(rough_model.scale_counts_per_mps2);
    v->wobble_amplitude_mps2 = std::sqrt((cos_mps2.squaredNorm() + sin_mps2.squaredNorm()) / 2.0);
    v->tilt_deg = std::asin(std::min(1.0, v->wobble_amplitude_mps2 / options.gravity_mps2)) * kDegreesPerRadian;
  }
  v->level = !options.judge_tilt || !(v->tilt_deg > options.max_tilt_deg);
}

// The median of `v` (non-empty), reordering it.
double MedianInPlace(std::vector<double>& v) {
  const auto middle = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), middle, v.end());
  return *middle;
}

// Check 4: the largest reading off the run's model (mean + swing), in robust sigmas per axis.
std::string CheckStill(const std::vector<Sample>& samples, const TurntableStabilityOptions& options,
                       TurntableVerdict* v) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> residual;
  for (const Sample& s : samples) {
    if (!IsFinite(s)) continue;
    residual.push_back(s.raw_counts - v->swing.At(s.t_s));
    mean += residual.back();
  }
  mean /= static_cast<double>(residual.size());
  v->still = true;
  double worst = 0.0;
  std::string reason;
  std::vector<double> dev(residual.size()), scratch;
  for (int axis = 0; axis < 3; ++axis) {
    for (size_t k = 0; k < residual.size(); ++k) dev[k] = std::fabs(residual[k][axis] - mean[axis]);
    scratch = dev;
    // The robust sigma, never below the rounding of whole counts (0.29).
    const double sigma = std::max(1.4826 * MedianInPlace(scratch), 0.29);
    size_t k_worst = 0;
    for (size_t k = 0; k < dev.size(); ++k)
      if (dev[k] > dev[k_worst]) k_worst = k;
    const double sigmas = dev[k_worst] / sigma;
    if (!(sigmas > options.spike_sigmas) || sigmas < worst) continue;
    worst = sigmas;
    v->still = false;
    size_t seen = 0;
    double t_s = kNaN;
    for (const Sample& s : samples)
      if (IsFinite(s) && seen++ == k_worst) t_s = s.t_s;
    reason = fmt::format("knocked: {} jumped {:.0f} counts ({:.0f} sigma) from the run at t = {:.2f} s",
                         kAxisLetters[axis], residual[k_worst][axis] - mean[axis], sigmas, t_s);
  }
  return reason;
}

std::string TiltReason(const TurntableVerdict& v, const TurntableStabilityOptions& options) {
  return fmt::format(
      "the turntable is tilted {:.2g} deg (gravity swings {:.2g} m/s^2 once per revolution), "
      "tolerance {:.3g} deg: level the turntable (a spirit level on its plate, turn its feet)",
      v.tilt_deg, v.wobble_amplitude_mps2, options.max_tilt_deg);
}

}  // namespace

std::string TurntableStabilityOptions::Validate() const {
  if (!(std::isfinite(gravity_mps2) && gravity_mps2 > 0.0))
    return fmt::format("gravity_mps2 is {}, must be > 0", gravity_mps2);
  if (!(centripetal_tolerance > 0.0 && centripetal_tolerance < 1.0))
    return fmt::format("centripetal_tolerance is {}, must be in (0, 1)", centripetal_tolerance);
  if (!(std::isfinite(speed_tolerance) && speed_tolerance > 0.0))
    return fmt::format("speed_tolerance is {}, must be > 0", speed_tolerance);
  if (!(std::isfinite(min_speed_spread_mps2) && min_speed_spread_mps2 >= 0.0))
    return fmt::format("min_speed_spread_mps2 is {}, must be >= 0", min_speed_spread_mps2);
  if (sub_windows < 2) return fmt::format("sub_windows is {}, must be >= 2", sub_windows);
  if (!(std::isfinite(max_tilt_deg) && max_tilt_deg > 0.0))
    return fmt::format("max_tilt_deg is {}, must be > 0 deg", max_tilt_deg);
  if (!(std::isfinite(spike_sigmas) && spike_sigmas > 0.0))
    return fmt::format("spike_sigmas is {}, must be > 0", spike_sigmas);
  if (!(std::isfinite(min_mounting_residual_mps2) && min_mounting_residual_mps2 > 0.0))
    return fmt::format("min_mounting_residual_mps2 is {}, must be > 0", min_mounting_residual_mps2);
  if (!(range_margin >= 0.0 && range_margin < 1.0))
    return fmt::format("range_margin is {}, must be in [0, 1)", range_margin);
  return {};
}

std::string TurntableSetup::Validate() const {
  if (!(std::isfinite(radius_m) && radius_m > 0.0))
    return fmt::format("radius is {} m, must be > 0", radius_m);
  if (!(std::isfinite(rpm) && rpm > 0.0)) return fmt::format("speed is {} rpm, must be > 0", rpm);
  if (!(radial_axis.norm() > 0.0 && up_axis.norm() > 0.0) ||
      std::fabs(radial_axis.normalized().dot(up_axis.normalized())) > 0.1) {
    return "the radial and up axes must be non-zero and perpendicular";
  }
  return {};
}

double TurntableSetup::ExpectedCentripetalMps2() const {
  const double w = RpmToRadPerS(rpm);
  return w * w * radius_m;
}

TurntableVerdict EvaluateTurntable(const std::vector<Sample>& samples,
                                   const SensorModel& rough_model, const TurntableSetup& setup,
                                   const TurntableStabilityOptions& options) {
  if (std::string e = options.Validate(); !e.empty()) throw Error("turntable options: " + e);
  if (std::string e = setup.Validate(); !e.empty()) throw Error("turntable setup: " + e);
  TurntableVerdict v;
  v.expected_centripetal_mps2 = setup.ExpectedCentripetalMps2();
  const ForceSeries series = ToForces(samples, rough_model);
  v.n_samples = static_cast<long>(series.t_s.size());
  if (v.n_samples < 3 || !(series.t_s.back() > series.t_s.front())) {
    v.reason = fmt::format("too few samples to judge the turntable run ({})", v.n_samples);
    return v;
  }
  CheckConsistent(series, setup, options, &v);
  CheckSteady(series, setup, options, &v);
  CheckLevel(samples, rough_model, setup, options, &v);
  const std::string knocked = CheckStill(samples, options, &v);
  v.steady = v.steady && v.still;
  std::string mounting;
  CheckMounting(MeanForce(series), setup, options, &v, &mounting);
  std::vector<std::string> failures;
  // A wrong mounting explains the other mismatches: it alone is said.
  if (!v.mounted_as_asked) failures.push_back(mounting);
  else if (!v.consistent) failures.push_back(MismatchReason(v, setup, options.centripetal_tolerance));
  if (!v.still) failures.push_back(knocked);
  else if (!v.steady) failures.push_back(UnsteadyReason(v, options));
  if (!v.level) failures.push_back(TiltReason(v, options));
  v.ok = failures.empty();
  v.reason = fmt::format("{}", fmt::join(failures, "; "));
  return v;
}

Eigen::Vector3d OncePerRevolution::At(double t_s) const {
  const double phase = w_rad_per_s * (t_s - t0_s);
  return cos_counts * std::cos(phase) + sin_counts * std::sin(phase);
}

void RemoveOncePerRevolution(std::vector<Sample>* samples, const OncePerRevolution& swing) {
  for (Sample& s : *samples)
    if (IsFinite(s)) s.raw_counts -= swing.At(s.t_s);
}

std::string CheckTurntablePlan(const TurntableSetup& setup, const SensorModel& rough_model,
                               const AdcRange& adc_range,
                               const TurntableStabilityOptions& options) {
  if (std::string e = setup.Validate(); !e.empty()) return e;
  const double c = setup.ExpectedCentripetalMps2();
  const Eigen::Vector3d planned = -c * setup.radial_axis.normalized() +
                                  options.gravity_mps2 * setup.up_axis.normalized();
  const Eigen::Vector3d raw = rough_model.Raw(planned);
  const double margin = options.range_margin * (adc_range.max_counts - adc_range.min_counts);
  for (int axis = 0; axis < 3; ++axis) {
    if (raw[axis] >= adc_range.min_counts + margin && raw[axis] <= adc_range.max_counts - margin)
      continue;
    const double k = rough_model.scale_counts_per_mps2[axis];
    const double b = rough_model.bias_counts[axis];
    std::string reason = fmt::format(
        "planned {:.4g} m/s^2 centripetal ({:.4g} rpm at {:.3g} m) exceeds the sensor's range on "
        "{} (about {:.3g}..{:.3g} m/s^2, less a {:.0f} % margin)", c, setup.rpm, setup.radius_m,
        kAxisLetters[axis], (adc_range.min_counts - b) / k, (adc_range.max_counts - b) / k,
        100.0 * options.range_margin);
    if (setup.radius_m > kLargestLikelyRadiusM) {
      reason += fmt::format("; {:.3g} m is an unusual radius: did you mean {:.3g} m?",
                            setup.radius_m, setup.radius_m / 100.0);
    }
    return reason;
  }
  return {};
}

}  // namespace accelcal
