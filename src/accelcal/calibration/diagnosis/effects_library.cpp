// The effects of effect.h. Parameters per axis are in axis order x, y, z.
#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/base/linear_algebra.h"
#include "accelcal/calibration/diagnosis/effect.h"

namespace accelcal {
namespace {

constexpr std::string_view kAxes = "xyz";

std::string PerAxis(const char* stem, int i) { return fmt::format("{}_{}", stem, kAxes[i]); }

int CountTurntable(const std::vector<FitCapture>& captures) {
  int n = 0;
  for (const FitCapture& c : captures) n += c.kind == CaptureKind::kTurntable;
  return n;
}

int CountDistinctRadii(const std::vector<FitCapture>& captures) {
  std::vector<double> radii;
  for (const FitCapture& c : captures) {
    if (c.kind != CaptureKind::kTurntable) continue;
    bool seen = false;
    for (double r : radii) seen |= std::fabs(r - c.radius_m) < 1e-4;
    if (!seen) radii.push_back(c.radius_m);
  }
  return static_cast<int>(radii.size());
}

// Spread (max - min) of a per-capture quantity; NaN when any capture lacks it.
template <typename Get>
double Spread(const std::vector<FitCapture>& captures, Get get) {
  double lo = INFINITY, hi = -INFINITY;
  for (const FitCapture& c : captures) {
    const double v = get(c);
    if (!std::isfinite(v)) return NAN;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return hi - lo;
}


// True when axis j's capture means, scaled to -1..1 over their range and kept where they are
// clearly non-zero (|x| > 0.2), support a quadratic: the design [1, x, x^2] is well conditioned.
bool SeesThreeLevels(const std::vector<FitCapture>& captures, int j) {
  double lo = INFINITY, hi = -INFINITY;
  for (const FitCapture& c : captures) {
    lo = std::min(lo, c.mean_counts(j));
    hi = std::max(hi, c.mean_counts(j));
  }
  if (!(hi > lo)) return false;
  std::vector<double> xs;
  for (const FitCapture& c : captures) {
    const double x = (2.0 * c.mean_counts(j) - lo - hi) / (hi - lo);
    if (std::fabs(x) > 0.2) xs.push_back(x);
  }
  if (xs.size() < 3) return false;
  Eigen::MatrixXd design(xs.size(), 3);
  for (size_t i = 0; i < xs.size(); ++i) design.row(i) << 1.0, xs[i], xs[i] * xs[i];
  for (int k = 0; k < 3; ++k) design.col(k).normalize();
  const Eigen::Vector3d sv = SingularValues(design);
  return sv(2) > 0.05 * sv(0);
}

// The stated centripetal acceleration of a turntable capture, m/s^2; NaN for a static one.
double CentripetalMps2(const FitCapture& c) {
  if (c.kind != CaptureKind::kTurntable) return kNaN;
  const double w = RpmToRadPerS(c.rpm);
  return w * w * c.radius_m;
}

// --- quadratic_nonlinearity ----------------------------------------------------------------
// raw_j = b_j + k_j u_j + q_j u_j^2 per axis (u = a^a, m/s^2): the seed assumed a linear
// response; the MMA7260Q datasheet allows +-1 % of full scale.
class QuadraticNonlinearity final : public Effect {
 public:
  std::string_view Name() const override { return "quadratic_nonlinearity"; }
  std::string_view Story() const override {
    return "the response is not quite linear: each axis adds a term in the square of its input";
  }
  int NumParameters() const override { return 3; }
  std::string ParameterName(int i) const override { return PerAxis("q", i); }
  std::string ParameterUnit(int) const override { return "counts/(m/s^2)^2"; }
  double ParameterScale(int i, const SensorModel& base, const EffectContext&) const override {
    return base.scale_counts_per_mps2(i) * 1e-5;  // ~1e-3 m/s^2 of error at 10 m/s^2
  }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    // A term in u^2 is told from bias and scale only where an axis sees three or more distinct
    // input levels that move the magnitude: +-g alone (plus the zero of the other faces, which
    // a magnitude fit barely feels) makes the quadratic look like a bias shift.
    for (int j = 0; j < 3; ++j)
      if (!SeesThreeLevels(captures, j))
        return fmt::format("axis {} sees fewer than three distinct non-zero input levels (tilted "
                           "poses or turntable runs give more)", kAxes[j]);
    return {};
  }
  void Correct(const double* q, const SensorModel& base, const FitCapture&, const EffectContext&,
               CorrectedCapture* out) const override {
    for (int j = 0; j < 3; ++j) {
      // Solve k u + q u^2 = d for the root near d / k, in the form stable as q -> 0.
      const double d = out->raw_counts(j) - base.bias_counts(j);
      const double k = base.scale_counts_per_mps2(j);
      const double disc = k * k + 4.0 * q[j] * d;
      const double u = disc > 0.0 ? 2.0 * d / (k + std::sqrt(disc)) : d / k;
      out->raw_counts(j) = base.bias_counts(j) + k * u;
    }
  }
  int CorrectionStage() const override { return 2; }
  bool CorrectsReadings() const override { return true; }
};

// --- temperature_bias ------------------------------------------------------------------------
class TemperatureBias final : public Effect {
 public:
  std::string_view Name() const override { return "temperature_bias"; }
  std::string_view Story() const override {
    return "the zero-g level moves with temperature (the seed names it as a variable effect)";
  }
  int NumParameters() const override { return 3; }
  std::string ParameterName(int i) const override { return PerAxis("tc_bias", i); }
  std::string ParameterUnit(int) const override { return "counts/degC"; }
  double ParameterScale(int i, const SensorModel& base, const EffectContext&) const override {
    return base.scale_counts_per_mps2(i) * 1e-4;
  }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    const double spread = Spread(captures, [](const FitCapture& c) { return c.mean_temp_c; });
    if (std::isnan(spread)) return "needs a temperature on every capture (the temp_c column)";
    if (spread < 1.0) return fmt::format("the temperature varied by only {:.2f} degC", spread);
    return {};
  }
  void Correct(const double* tc, const SensorModel&, const FitCapture& c, const EffectContext& ctx,
               CorrectedCapture* out) const override {
    const double dt_c = c.mean_temp_c - ctx.temp_ref_c;
    for (int j = 0; j < 3; ++j) out->raw_counts(j) -= tc[j] * dt_c;
  }
  std::string_view RegressorName() const override { return "temperature"; }
  double Regressor(const FitCapture& c) const override { return c.mean_temp_c; }
  int CorrectionStage() const override { return 0; }
  bool CorrectsReadings() const override { return true; }
};

// --- temperature_scale -----------------------------------------------------------------------
class TemperatureScale final : public Effect {
 public:
  std::string_view Name() const override { return "temperature_scale"; }
  std::string_view Story() const override {
    return "the sensitivity changes with temperature";
  }
  int NumParameters() const override { return 3; }
  std::string ParameterName(int i) const override { return PerAxis("tc_scale", i); }
  std::string ParameterUnit(int) const override { return "1/degC"; }
  double ParameterScale(int, const SensorModel&, const EffectContext&) const override { return 1e-5; }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    const double spread = Spread(captures, [](const FitCapture& c) { return c.mean_temp_c; });
    if (std::isnan(spread)) return "needs a temperature on every capture (the temp_c column)";
    if (spread < 1.0) return fmt::format("the temperature varied by only {:.2f} degC", spread);
    return {};
  }
  void Correct(const double* tc, const SensorModel& base, const FitCapture& c,
               const EffectContext& ctx, CorrectedCapture* out) const override {
    // raw = b + k (1 + tc dT) u  =>  what the base model should see: b + (raw - b) / (1 + tc dT).
    const double dt_c = c.mean_temp_c - ctx.temp_ref_c;
    for (int j = 0; j < 3; ++j)
      out->raw_counts(j) = base.bias_counts(j) +
                           (out->raw_counts(j) - base.bias_counts(j)) / (1.0 + tc[j] * dt_c);
  }
  std::string_view RegressorName() const override { return "temperature"; }
  double Regressor(const FitCapture& c) const override { return c.mean_temp_c; }
  int CorrectionStage() const override { return 1; }
  bool CorrectsReadings() const override { return true; }
};

// --- bias_drift ------------------------------------------------------------------------------
class BiasDrift final : public Effect {
 public:
  std::string_view Name() const override { return "bias_drift"; }
  std::string_view Story() const override {
    return "the zero-g level drifts steadily during the session (the seed's random drift, over "
           "the session's span)";
  }
  int NumParameters() const override { return 3; }
  std::string ParameterName(int i) const override { return PerAxis("drift", i); }
  std::string ParameterUnit(int) const override { return "counts/s"; }
  double ParameterScale(int i, const SensorModel& base, const EffectContext&) const override {
    return base.scale_counts_per_mps2(i) * 1e-6;
  }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    const double span = Spread(captures, [](const FitCapture& c) { return c.mean_t_s; });
    if (std::isnan(span)) return "needs the capture times";
    if (span < 60.0) return fmt::format("the captures span only {:.0f} s", span);
    return {};
  }
  void Correct(const double* drift, const SensorModel&, const FitCapture& c,
               const EffectContext& ctx, CorrectedCapture* out) const override {
    const double dt_s = c.mean_t_s - ctx.t_ref_s;
    for (int j = 0; j < 3; ++j) out->raw_counts(j) -= drift[j] * dt_s;
  }
  std::string_view RegressorName() const override { return "time"; }
  double Regressor(const FitCapture& c) const override { return c.mean_t_s; }
  int CorrectionStage() const override { return 0; }
  bool CorrectsReadings() const override { return false; }  // a session artifact, see README
};

// --- radius_offset ---------------------------------------------------------------------------
class RadiusOffset final : public Effect {
 public:
  std::string_view Name() const override { return "radius_offset"; }
  std::string_view Story() const override {
    return "the sensing point is not where the radius was measured: every radius is off by the "
           "same length";
  }
  int NumParameters() const override { return 1; }
  std::string ParameterName(int) const override { return "dr"; }
  std::string ParameterUnit(int) const override { return "m"; }
  double ParameterScale(int, const SensorModel&, const EffectContext&) const override { return 1e-5; }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    if (CountDistinctRadii(captures) < 2) return "needs turntable captures at two radii or more";
    return {};
  }
  void Correct(const double* dr, const SensorModel&, const FitCapture& c, const EffectContext&,
               CorrectedCapture* out) const override {
    if (c.kind == CaptureKind::kTurntable) out->radius_m += dr[0];
  }
  std::string_view RegressorName() const override { return "w^2 r"; }
  double Regressor(const FitCapture& c) const override { return CentripetalMps2(c); }
  int CorrectionStage() const override { return 3; }
  bool CorrectsReadings() const override { return false; }
};

// --- rpm_scale -------------------------------------------------------------------------------
class RpmScale final : public Effect {
 public:
  std::string_view Name() const override { return "rpm_scale"; }
  std::string_view Story() const override {
    return "the turntable turns at a slightly different speed than stated";
  }
  int NumParameters() const override { return 1; }
  std::string ParameterName(int) const override { return "rpm_scale"; }
  std::string ParameterUnit(int) const override { return "1"; }
  double ParameterScale(int, const SensorModel&, const EffectContext&) const override { return 1e-5; }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    if (CountTurntable(captures) < 2) return "needs two turntable captures or more";
    return {};
  }
  void Correct(const double* s, const SensorModel&, const FitCapture& c, const EffectContext&,
               CorrectedCapture* out) const override {
    if (c.kind == CaptureKind::kTurntable) out->omega_rad_per_s *= 1.0 + s[0];
  }
  std::string_view RegressorName() const override { return "w^2 r"; }
  double Regressor(const FitCapture& c) const override { return CentripetalMps2(c); }
  int CorrectionStage() const override { return 3; }
  bool CorrectsReadings() const override { return false; }
};

// --- size_effect -----------------------------------------------------------------------------
// Each axis's proof mass sits d_j along its own axis from the nominal sensing point; an axis in
// the table's plane then feels the centripetal acceleration of its own radius: -w^2 d_j extra
// along itself (radial or tangential alike); the vertical axis feels none.
class SizeEffect final : public Effect {
 public:
  std::string_view Name() const override { return "size_effect"; }
  std::string_view Story() const override {
    return "each axis's proof mass sits at its own radius, so each feels its own centripetal "
           "acceleration";
  }
  int NumParameters() const override { return 3; }
  std::string ParameterName(int i) const override { return PerAxis("d", i); }
  std::string ParameterUnit(int) const override { return "m"; }
  double ParameterScale(int, const SensorModel&, const EffectContext&) const override { return 1e-5; }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    int known = 0;
    std::array<bool, 3> in_plane{false, false, false};
    for (const FitCapture& c : captures) {
      if (c.kind != CaptureKind::kTurntable) continue;
      if (!c.up_axis) return "needs the mounting of every turntable capture (the up_axis column)";
      ++known;
      const Eigen::Vector3d up = SensorAxisVector(*c.up_axis);
      for (int j = 0; j < 3; ++j) in_plane[j] = in_plane[j] || std::fabs(up(j)) < 0.5;
    }
    if (known < 3) return "needs three turntable captures or more";
    for (int j = 0; j < 3; ++j)
      if (!in_plane[j]) return fmt::format("axis {} never lies in the table's plane", kAxes[j]);
    return {};
  }
  void Correct(const double* d, const SensorModel& base, const FitCapture& c, const EffectContext&,
               CorrectedCapture* out) const override {
    if (c.kind != CaptureKind::kTurntable || !c.up_axis) return;
    const Eigen::Vector3d up = SensorAxisVector(*c.up_axis);
    const double w2 = out->omega_rad_per_s * out->omega_rad_per_s;
    for (int j = 0; j < 3; ++j) {
      const double in_plane = 1.0 - up(j) * up(j);
      out->raw_counts(j) += base.scale_counts_per_mps2(j) * w2 * d[j] * in_plane;
    }
  }
  std::string_view RegressorName() const override { return "w^2 r"; }
  double Regressor(const FitCapture& c) const override { return CentripetalMps2(c); }
  int CorrectionStage() const override { return 3; }
  bool CorrectsReadings() const override { return false; }
};

}  // namespace

const std::vector<const Effect*>& AllEffects() {
  static const QuadraticNonlinearity quadratic;
  static const TemperatureBias temperature_bias;
  static const TemperatureScale temperature_scale;
  static const BiasDrift bias_drift;
  static const RadiusOffset radius_offset;
  static const RpmScale rpm_scale;
  static const SizeEffect size_effect;
  static const std::vector<const Effect*> all = {&quadratic,  &temperature_bias, &temperature_scale,
                                                 &bias_drift, &radius_offset,    &rpm_scale,
                                                 &size_effect};
  return all;
}

std::vector<const Effect*> InCorrectionOrder(std::vector<const Effect*> effects) {
  std::stable_sort(effects.begin(), effects.end(), CorrectsBefore);
  return effects;
}

const Effect* FindEffect(std::string_view name) {
  for (const Effect* e : AllEffects())
    if (e->Name() == name) return e;
  return nullptr;
}

}  // namespace accelcal
