#include "accelcal/acquire/capture_engine/turntable_stability.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;
constexpr char kAxisNames[3] = {'x', 'y', 'z'};
// Above this an entered radius is more likely a unit slip than a bench turntable, m.
constexpr double kLargestLikelyRadiusM = 2.0;

bool IsFinite(const Sample& s) { return std::isfinite(s.t_s) && s.raw_counts.allFinite(); }

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
      "and radius (the measurement fits {:.4g} rpm at {:.3g} m)",
      v.expected_centripetal_mps2, setup.rpm, setup.radius_m, v.measured_centripetal_mps2,
      setup.rpm * std::sqrt(std::max(v.centripetal_ratio, 0.0)), setup.radius_m);
}

// Check 1: the horizontal part of the mean force against w^2 r.
void CheckConsistent(const ForceSeries& series, const TurntableSetup& setup,
                     const TurntableStabilityOptions& options, TurntableVerdict* v) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& f : series.f_mps2) mean += f;
  mean /= static_cast<double>(series.f_mps2.size());
  const Eigen::Vector3d up = setup.up_axis.normalized();
  v->mean_magnitude_mps2 = mean.norm();
  v->measured_centripetal_mps2 = (mean - mean.dot(up) * up).norm();
  v->centripetal_ratio = v->measured_centripetal_mps2 / v->expected_centripetal_mps2;
  v->consistent = std::fabs(v->centripetal_ratio - 1.0) <= options.centripetal_tolerance;
}

// Checks 2 and 3: the wobble's sine, then the sub-window means without it.
void CheckSteadyAndLevel(const ForceSeries& series, const TurntableSetup& setup,
                         const TurntableStabilityOptions& options, TurntableVerdict* v) {
  const Eigen::Vector3d radial = setup.radial_axis.normalized();
  std::vector<double> radial_mps2(series.f_mps2.size());
  for (size_t k = 0; k < radial_mps2.size(); ++k) radial_mps2[k] = series.f_mps2[k].dot(radial);
  const double w = RpmToRadPerS(setup.rpm);
  const double span_s = series.t_s.back() - series.t_s.front();
  Eigen::Vector3d sine = Eigen::Vector3d::Zero();
  // Under one revolution the sine cannot be told from a trend: leave the wobble unmeasured.
  if (w * span_s >= 2.0 * M_PI) {
    sine = FitOncePerRevolution(series.t_s, radial_mps2, w);
    v->wobble_amplitude_mps2 = std::hypot(sine[1], sine[2]);
    v->tilt_deg = std::asin(std::min(1.0, v->wobble_amplitude_mps2 / options.gravity_mps2)) *
                  kRadToDeg;
  }
  v->level = !(v->tilt_deg > options.max_tilt_deg);

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

std::string TiltReason(const TurntableVerdict& v, const TurntableStabilityOptions& options) {
  return fmt::format(
      "table tilted {:.2g} deg (wobble {:.2g} m/s^2 once per revolution), limit {:.3g} deg: level "
      "the turntable", v.tilt_deg, v.wobble_amplitude_mps2, options.max_tilt_deg);
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
  CheckSteadyAndLevel(series, setup, options, &v);
  std::vector<std::string> failures;
  if (!v.consistent) failures.push_back(MismatchReason(v, setup, options.centripetal_tolerance));
  if (!v.steady) failures.push_back(UnsteadyReason(v, options));
  if (!v.level) failures.push_back(TiltReason(v, options));
  v.ok = failures.empty();
  v.reason = fmt::format("{}", fmt::join(failures, "; "));
  return v;
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
        kAxisNames[axis], (adc_range.min_counts - b) / k, (adc_range.max_counts - b) / k,
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
