// The sensor's own effects (effect.h): its response's nonlinearity and cross-axis coupling, its
// temperature dependence, and the drift of its zero-g level over the session. Parameters per
// axis are in axis order x, y, z; u = a^a = K^-1 (raw - b) in m/s^2 (sensor_model.h).
#include <algorithm>
#include <cmath>
#include <type_traits>

#include <fmt/core.h>

#include "accelcal/base/linear_algebra.h"
#include "accelcal/calibration/diagnosis/effect_support.h"

namespace accelcal::effects {
namespace {

constexpr std::string_view kAxes = "xyz";

// The largest |u_j| over the captures, m/s^2.
Eigen::Vector3d LargestInputs(const std::vector<FitCapture>& captures, const SensorModel& base) {
  Eigen::Vector3d largest = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& u : Inputs(captures, base)) largest = largest.cwiseMax(u.cwiseAbs());
  return largest;
}

// Empty when a term of `power` in u, coefficient theta_j counts/(m/s^2)^power, stays within the
// nonlinearity bound at the largest input of each axis; else why not.
std::string NonlinearityBeyondBound(const double* theta, int power, const SensorModel& base,
                                    const std::vector<FitCapture>& captures) {
  const Eigen::Vector3d largest = LargestInputs(captures, base);
  const double bound_mps2 = kMaxNonlinearityFraction * kFullScaleMps2;
  for (int j = 0; j < 3; ++j) {
    const double term_mps2 =
        std::fabs(theta[j]) * std::pow(largest(j), power) / base.scale_counts_per_mps2(j);
    if (term_mps2 > bound_mps2)
      return fmt::format("on axis {} it amounts to {:.3g} m/s^2 at {:.3g} m/s^2, beyond {:.0f} % "
                         "of a 6 g full scale ({:.2f} m/s^2; the MMA7260Q's worst case is 1 %)",
                         kAxes[j], term_mps2, largest(j), 100.0 * kMaxNonlinearityFraction,
                         bound_mps2);
  }
  return {};
}

std::string NeedsTemperature(const std::vector<FitCapture>& captures) {
  const double spread = SpreadOfTemperature(captures);
  if (std::isnan(spread)) return "needs a temperature on every capture (the temp_c column)";
  if (spread < 1.0) return fmt::format("the temperature varied by only {:.2f} degC", spread);
  return {};
}

// --- quadratic_nonlinearity ----------------------------------------------------------------
// raw_j = b_j + k_j u_j + q_j u_j^2 per axis: the seed assumed a linear response; the MMA7260Q
// datasheet allows +-1 % of full scale.
class QuadraticNonlinearity final : public DifferentiableEffect<QuadraticNonlinearity> {
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
      if (!SeesLevelsFor(captures, j, 2))
        return fmt::format("axis {} sees fewer than three distinct non-zero input levels (tilted "
                           "poses or turntable runs give more)", kAxes[j]);
    return {};
  }
  std::string_view CapturePlan() const override {
    return "three or more distinct non-zero input levels per axis (tilted poses or turntable runs)";
  }
  std::string WhyImplausible(const double* q, const SensorModel& base,
                             const std::vector<FitCapture>& captures) const override {
    return NonlinearityBeyondBound(q, 2, base, captures);
  }
  template <class S, class Base>
  void Apply(const S* q, const Base& base, const FitCapture&, const EffectContext&,
             CorrectedCaptureOf<S>* out) const {
    using std::sqrt;
    for (int j = 0; j < 3; ++j) {
      // Solve k u + q u^2 = d for the root near d / k, in the form stable as q -> 0.
      const S d = out->raw_counts(j) - base.bias_counts(j);
      const S k = base.scale_counts_per_mps2(j);
      const S disc = k * k + 4.0 * q[j] * d;
      S u = d / k;
      if (disc > 0.0) u = 2.0 * d / (k + sqrt(disc));
      out->raw_counts(j) = base.bias_counts(j) + k * u;
    }
  }
  int CorrectionStage() const override { return 2; }
  bool CorrectsReadings() const override { return true; }
  std::optional<CCorrection> InC() const override {
    // The same root as Apply's, in the same stable form.
    return CCorrection{
        {{"quadratic_nonlinearity: q (counts per (m/s^2)^2)", "accelcal_quadratic_counts_per_mps2_sq",
          PerAxisNames("q")}},
        "  /* quadratic_nonlinearity: d = k u + q u^2, solved for u (root near d/k) */\n"
        "  for (j = 0; j < 3; ++j) {\n"
        "    const ACCELCAL_REAL k = accelcal_scale_counts_per_mps2[j];\n"
        "    const ACCELCAL_REAL disc = k * k + 4 * accelcal_quadratic_counts_per_mps2_sq[j] * d[j];\n"
        "    if (disc > 0) d[j] = k * (2 * d[j] / (k + (ACCELCAL_REAL)sqrt((double)disc)));\n"
        "  }\n",
        true, {"sqrt"}};
  }
  std::string_view PlainName() const override { return "a bent response"; }
  std::optional<BenchStatement> InBenchTerms(std::span<const double> q, std::span<const double>, std::string_view,
                                             double g) const override {
    // q g^2: the term at 1 g, counts.
    return PerAxisStatement("the sensor's output is not quite a straight line: at 1 g it bends by ", q, g * g, 1,
                            "counts");
  }
};

// --- cubic_nonlinearity --------------------------------------------------------------------
// raw_j = b_j + k_j u_j + c3_j u_j^3: a response that bends symmetrically, compressing (c3 < 0)
// or stretching toward both ends of the range alike; odd, so it does not move the zero-g level
// and +-g alone cannot tell it from the scale.
class CubicNonlinearity final : public DifferentiableEffect<CubicNonlinearity> {
 public:
  std::string_view Name() const override { return "cubic_nonlinearity"; }
  std::string_view Story() const override {
    return "the response bends alike toward both ends of the range: each axis adds a term in the "
           "cube of its input";
  }
  int NumParameters() const override { return 3; }
  std::string ParameterName(int i) const override { return PerAxis("c3", i); }
  std::string ParameterUnit(int) const override { return "counts/(m/s^2)^3"; }
  double ParameterScale(int i, const SensorModel& base, const EffectContext&) const override {
    return base.scale_counts_per_mps2(i) * 1e-6;  // ~1e-3 m/s^2 of error at 10 m/s^2
  }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    for (int j = 0; j < 3; ++j)
      if (!SeesLevelsFor(captures, j, 3))
        return fmt::format("axis {} sees fewer than two distinct non-zero input magnitudes (+-g "
                           "alone makes u^3 look like the scale; tilted poses or turntable runs "
                           "give more)", kAxes[j]);
    return {};
  }
  std::string_view CapturePlan() const override {
    return "two or more distinct non-zero input magnitudes per axis besides +-g (tilted poses at "
           "g/sqrt(3), turntable runs above g)";
  }
  std::string WhyImplausible(const double* c3, const SensorModel& base,
                             const std::vector<FitCapture>& captures) const override {
    return NonlinearityBeyondBound(c3, 3, base, captures);
  }
  template <class S, class Base>
  void Apply(const S* c3, const Base& base, const FitCapture&, const EffectContext&,
             CorrectedCaptureOf<S>* out) const {
    for (int j = 0; j < 3; ++j) {
      const S d = out->raw_counts(j) - base.bias_counts(j);
      const S k = base.scale_counts_per_mps2(j);
      const double u = SolveCubic(ValueOf(k), ValueOf(c3[j]), ValueOf(d));
      if constexpr (std::is_same_v<S, double>) {
        out->raw_counts(j) = base.bias_counts(j) + k * u;
      } else {
        // The root's derivatives, by the implicit function theorem: one Newton step from the
        // solved root carries them exactly. Its value moves by round-off only, and is set back
        // to the double correction's, so that a residual is the same with derivatives or not.
        const S step = (k * u + c3[j] * (u * u * u) - d) / (k + 3.0 * c3[j] * (u * u));
        out->raw_counts(j) = base.bias_counts(j) + k * (u - step);
        out->raw_counts(j).value() = ValueOf(base.bias_counts(j)) + ValueOf(k) * u;
      }
    }
  }
  int CorrectionStage() const override { return 2; }
  bool CorrectsReadings() const override { return true; }
  std::optional<CCorrection> InC() const override {
    // SolveCubic's Newton steps, with its stop where the slope collapses.
    return CCorrection{
        {{"cubic_nonlinearity: c3 (counts per (m/s^2)^3)", "accelcal_cubic_counts_per_mps2_cu", PerAxisNames("c3")}},
        "  /* cubic_nonlinearity: d = k u + c3 u^3, solved for u by Newton from d/k */\n"
        "  for (j = 0; j < 3; ++j) {\n"
        "    const ACCELCAL_REAL k = accelcal_scale_counts_per_mps2[j];\n"
        "    const ACCELCAL_REAL c3 = accelcal_cubic_counts_per_mps2_cu[j];\n"
        "    ACCELCAL_REAL u = d[j] / k;\n"
        "    int it;\n"
        "    for (it = 0; it < 4; ++it) {\n"
        "      const ACCELCAL_REAL slope = k + 3 * c3 * u * u;\n"
        "      if (!(slope * slope > (ACCELCAL_REAL)0.01 * k * k)) break;\n"
        "      u -= (k * u + c3 * u * u * u - d[j]) / slope;\n"
        "    }\n"
        "    d[j] = k * u;\n"
        "  }\n",
        true, {}};
  }
  std::string_view PlainName() const override { return "an S-shaped response"; }
  std::optional<BenchStatement> InBenchTerms(std::span<const double> c3, std::span<const double>, std::string_view,
                                             double g) const override {
    // c3 g^3: the term at 1 g, counts.
    return PerAxisStatement("the sensor's output is not quite a straight line (an S-bend): at 1 g by ", c3,
                            g * g * g, 1, "counts");
  }

 private:
  // The root of k u + c3 u^3 = d near d / k, by Newton from there: the term is a small
  // fraction of k u, so four steps reach machine precision, and usually two: a step within
  // round-off of u (two units in the last place) ends it, the rest would only move u within
  // round-off (this correction runs in every residual of every fit of the diagnosis: issue 18).
  static double SolveCubic(double k, double c3, double d) {
    double u = d / k;
    for (int it = 0; it < 4; ++it) {
      const double slope = k + 3.0 * c3 * u * u;
      if (!(std::fabs(slope) > 0.1 * std::fabs(k))) break;  // far outside the bound: stop
      const double step = (k * u + c3 * u * u * u - d) / slope;
      u -= step;
      if (std::fabs(step) <= 4.5e-16 * std::fabs(u)) break;
    }
    return u;
  }
};

// --- cross_axis_coupling -------------------------------------------------------------------
// a^a_j += kappa_j u_k u_l, (j, k, l) = (x, y, z), (y, z, x), (z, x, y): each axis also responds
// to the product of the other two inputs (a second-order cross-axis term of the suspension).
// A magnitude fit sees only the sum: |a| changes by (u_x u_y u_z / |u|) (kappa_x + kappa_y +
// kappa_z), so the one parameter is kappa = that sum, and the correction shares it equally
// (kappa / 3 per axis): right for |a|, not resolved per axis.
class CrossAxisCoupling final : public DifferentiableEffect<CrossAxisCoupling> {
 public:
  std::string_view Name() const override { return "cross_axis_coupling"; }
  std::string_view Story() const override {
    return "each axis also responds to the product of the other two inputs (second-order "
           "cross-axis coupling; a magnitude fit sees only its sum over the axes)";
  }
  int NumParameters() const override { return 1; }
  std::string ParameterName(int) const override { return "kappa"; }
  std::string ParameterUnit(int) const override { return "1/(m/s^2)"; }
  double ParameterScale(int, const SensorModel&, const EffectContext& ctx) const override {
    const double corner = ctx.gravity_mps2 * ctx.gravity_mps2 / (3.0 * std::sqrt(3.0));
    return 1e-3 / corner;  // 1e-3 m/s^2 on a (1,1,1) corner pose
  }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    // It acts through u_x u_y u_z: only poses that load all three axes (corners) see it, and it
    // must not be a combination of the pair products that carry the misalignment.
    const std::vector<Eigen::Vector3d> d = RoughDirections(captures);
    int corners = 0;
    Eigen::MatrixXd design(d.size(), 4);
    for (size_t i = 0; i < d.size(); ++i) {
      const double triple = d[i].x() * d[i].y() * d[i].z();
      corners += std::fabs(triple) > 0.05;
      design.row(i) << d[i].x() * d[i].y(), d[i].x() * d[i].z(), d[i].y() * d[i].z(), triple;
    }
    if (corners < 2) return "needs two or more poses that load all three axes (corners)";
    for (int k = 0; k < 4; ++k) {
      if (!(design.col(k).norm() > 0.0)) return "the poses leave an axis pair unloaded";
      design.col(k).normalize();
    }
    const Eigen::VectorXd sv = SingularValues(design);
    if (!(sv(3) > 0.05 * sv(0)))
      return "its corner poses cannot tell it from the misalignment (add a corner with another "
             "sign of u_x u_y u_z)";
    return {};
  }
  std::string_view CapturePlan() const override {
    return "poses that load all three axes (corners), with both signs of u_x u_y u_z, beside the "
           "misalignment's tilted poses";
  }
  std::string WhyImplausible(const double* kappa, const SensorModel& base,
                             const std::vector<FitCapture>& captures) const override {
    double largest_mps2 = 0.0;
    for (const Eigen::Vector3d& u : Inputs(captures, base)) largest_mps2 = std::max(largest_mps2, u.norm());
    // The largest product of two components of an input of size |u| is |u|^2 / 2.
    const double term_mps2 = std::fabs(kappa[0]) * largest_mps2 * largest_mps2 / 2.0;
    const double bound_mps2 = kMaxNonlinearityFraction * kFullScaleMps2;
    if (term_mps2 > bound_mps2)
      return fmt::format("it amounts to {:.3g} m/s^2 at {:.3g} m/s^2, beyond {:.0f} % of a 6 g "
                         "full scale ({:.2f} m/s^2)", term_mps2, largest_mps2,
                         100.0 * kMaxNonlinearityFraction, bound_mps2);
    return {};
  }
  template <class S, class Base>
  void Apply(const S* kappa, const Base& base, const FitCapture&, const EffectContext&,
             CorrectedCaptureOf<S>* out) const {
    S u[3];
    for (int j = 0; j < 3; ++j)
      u[j] = (out->raw_counts(j) - base.bias_counts(j)) / base.scale_counts_per_mps2(j);
    const S products[3] = {u[1] * u[2], u[2] * u[0], u[0] * u[1]};
    for (int j = 0; j < 3; ++j)
      out->raw_counts(j) -= base.scale_counts_per_mps2(j) * kappa[0] / 3.0 * products[j];
  }
  int CorrectionStage() const override { return 2; }
  bool CorrectsReadings() const override { return true; }
  std::optional<CCorrection> InC() const override {
    return CCorrection{
        {{"cross_axis_coupling: kappa (per m/s^2)", "accelcal_cross_kappa_per_mps2", {"kappa"}}},
        "  /* cross_axis_coupling: each axis also reads kappa/3 times the product of the other two\n"
        "     inputs (a magnitude fit sees only the sum kappa: shared equally) */\n"
        "  {\n"
        "    ACCELCAL_REAL u[3];\n"
        "    for (j = 0; j < 3; ++j) u[j] = d[j] / accelcal_scale_counts_per_mps2[j];\n"
        "    d[0] -= accelcal_scale_counts_per_mps2[0] * accelcal_cross_kappa_per_mps2 / 3 * u[1] * u[2];\n"
        "    d[1] -= accelcal_scale_counts_per_mps2[1] * accelcal_cross_kappa_per_mps2 / 3 * u[2] * u[0];\n"
        "    d[2] -= accelcal_scale_counts_per_mps2[2] * accelcal_cross_kappa_per_mps2 / 3 * u[0] * u[1];\n"
        "  }\n",
        true, {}};
  }
  std::string_view PlainName() const override { return "axes responding to each other"; }
  std::string_view ReportNote() const override {
    return "a magnitude fit sees only the sum kappa over the three axes of their coupling to the product of "
           "the other two inputs; the correction shares it equally (right for |a|, not resolved per axis).";
  }
  std::optional<BenchStatement> InBenchTerms(std::span<const double> values, std::span<const double>,
                                             std::string_view, double g) const override {
    const double kappa = FirstOf(values);
    if (!std::isfinite(kappa)) return std::nullopt;
    // The corner pose (1, 1, 1)/sqrt(3) loads u_x u_y u_z = g^3 / (3 sqrt 3), where the
    // coupling shows most: |a| moves by kappa times that over |u| = g.
    const double corner_mps2 = g * g / (3.0 * std::sqrt(3.0));
    BenchStatement s{"each axis also responds to the other two together: ", {}, " on a corner pose"};
    s.size.shape = BenchQuantity::Shape::kValue;
    s.size.values = {kappa * corner_mps2 * 1000.0};
    s.size.unit = "mm/s^2";
    return s;
  }
};

// --- temperature_bias ------------------------------------------------------------------------
// The bound: 5 mg/degC, accelcal's (about ten times a consumer MEMS part's typical zero-g drift).
constexpr double kMaxTempBiasMps2PerC = 0.05;
// 0.1 %/degC, accelcal's (about ten times a typical sensitivity drift).
constexpr double kMaxTempScalePerC = 1e-3;

// What the temperature effects share: a temperature on every capture identifies them, they grow
// with it, and they read it in every reading they correct.
template <class Derived>
class TemperatureEffect : public DifferentiableEffect<Derived> {
 public:
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    return NeedsTemperature(captures);
  }
  std::string_view CapturePlan() const override {
    return "a temperature on every capture, varying by 1 degC or more (and not in step with time)";
  }
  std::string_view RegressorName() const override { return "temperature"; }
  double Regressor(const FitCapture& c) const override { return c.mean_temp_c; }
  bool CorrectsReadings() const override { return true; }
  bool ReadsTemperature() const override { return true; }
};

class TemperatureBias final : public TemperatureEffect<TemperatureBias> {
 public:
  std::string_view Name() const override { return "temperature_bias"; }
  std::string_view Story() const override {
    return "the zero-g level moves with temperature (the lab chapter names it as a variable effect)";
  }
  int NumParameters() const override { return 3; }
  std::string ParameterName(int i) const override { return PerAxis("tc_bias", i); }
  std::string ParameterUnit(int) const override { return "counts/degC"; }
  double ParameterScale(int i, const SensorModel& base, const EffectContext&) const override {
    return base.scale_counts_per_mps2(i) * 1e-4;
  }
  std::string WhyImplausible(const double* tc, const SensorModel& base,
                             const std::vector<FitCapture>&) const override {
    for (int j = 0; j < 3; ++j) {
      const double mps2_per_c = std::fabs(tc[j]) / base.scale_counts_per_mps2(j);
      if (mps2_per_c > kMaxTempBiasMps2PerC)
        return fmt::format("axis {} would move {:.3g} m/s^2 per degC, beyond {:g} (5 mg/degC)",
                           kAxes[j], mps2_per_c, kMaxTempBiasMps2PerC);
    }
    return {};
  }
  template <class S, class Base>
  void Apply(const S* tc, const Base&, const FitCapture& c, const EffectContext& ctx,
             CorrectedCaptureOf<S>* out) const {
    const double dt_c = c.mean_temp_c - ctx.temp_ref_c;
    for (int j = 0; j < 3; ++j) out->raw_counts(j) -= tc[j] * dt_c;
  }
  int CorrectionStage() const override { return 0; }
  std::optional<CCorrection> InC() const override {
    return CCorrection{
        {{"", "accelcal_tc_bias_counts_per_degc", PerAxisNames("tc_bias")}},
        "  /* temperature_bias: the zero-g level moves by tc counts per degC */\n"
        "  for (j = 0; j < 3; ++j) d[j] -= accelcal_tc_bias_counts_per_degc[j] * dt_c;\n",
        false, {}};
  }
  std::string_view PlainName() const override { return "a zero-g level moving with temperature"; }
  std::optional<BenchStatement> InBenchTerms(std::span<const double> tc, std::span<const double>, std::string_view,
                                             double) const override {
    return PerAxisStatement("the zero-g level moves with temperature: ", tc, 1.0, 2, "counts per degC");
  }
};

// --- temperature_scale -----------------------------------------------------------------------
class TemperatureScale final : public TemperatureEffect<TemperatureScale> {
 public:
  std::string_view Name() const override { return "temperature_scale"; }
  std::string_view Story() const override {
    return "the sensitivity changes with temperature";
  }
  int NumParameters() const override { return 3; }
  std::string ParameterName(int i) const override { return PerAxis("tc_scale", i); }
  std::string ParameterUnit(int) const override { return "1/degC"; }
  double ParameterScale(int, const SensorModel&, const EffectContext&) const override { return 1e-5; }
  std::string WhyImplausible(const double* tc, const SensorModel&,
                             const std::vector<FitCapture>&) const override {
    for (int j = 0; j < 3; ++j)
      if (std::fabs(tc[j]) > kMaxTempScalePerC)
        return fmt::format("axis {} would change its sensitivity by {:.3g} per degC, beyond {:g} "
                           "(0.1 %/degC)", kAxes[j], tc[j], kMaxTempScalePerC);
    return {};
  }
  template <class S, class Base>
  void Apply(const S* tc, const Base& base, const FitCapture& c, const EffectContext& ctx,
             CorrectedCaptureOf<S>* out) const {
    // raw = b + k (1 + tc dT) u  =>  what the base model should see: b + (raw - b) / (1 + tc dT).
    const double dt_c = c.mean_temp_c - ctx.temp_ref_c;
    for (int j = 0; j < 3; ++j)
      out->raw_counts(j) = base.bias_counts(j) +
                           (out->raw_counts(j) - base.bias_counts(j)) / (1.0 + tc[j] * dt_c);
  }
  int CorrectionStage() const override { return 1; }
  std::optional<CCorrection> InC() const override {
    return CCorrection{
        {{"", "accelcal_tc_scale_per_degc", PerAxisNames("tc_scale")}},
        "  /* temperature_scale: the sensitivity is k (1 + tc dT) */\n"
        "  for (j = 0; j < 3; ++j) d[j] /= (ACCELCAL_REAL)1 + accelcal_tc_scale_per_degc[j] * dt_c;\n",
        false, {}};
  }
  std::string_view PlainName() const override { return "a sensitivity changing with temperature"; }
  std::optional<BenchStatement> InBenchTerms(std::span<const double> tc, std::span<const double>, std::string_view,
                                             double) const override {
    return PerAxisStatement("the sensitivity changes with temperature: ", tc, 100.0, 3, "% per degC");
  }
};

// --- bias_drift ------------------------------------------------------------------------------
// The bound: the zero-g level may drift by 1 % of a 6 g full scale over the session (accelcal's).
constexpr double kMaxDriftFractionOfFullScale = 0.01;

class BiasDrift final : public DifferentiableEffect<BiasDrift> {
 public:
  std::string_view Name() const override { return "bias_drift"; }
  std::string_view Story() const override {
    return "the zero-g level drifts steadily during the session (the lab chapter's random drift, over "
           "the session's span)";
  }
  int NumParameters() const override { return 3; }
  std::string ParameterName(int i) const override { return PerAxis("drift", i); }
  std::string ParameterUnit(int) const override { return "counts/s"; }
  double ParameterScale(int i, const SensorModel& base, const EffectContext&) const override {
    return base.scale_counts_per_mps2(i) * 1e-6;
  }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    const double span = SpreadOfTime(captures);
    if (std::isnan(span)) return "needs the capture times";
    if (span < 60.0) return fmt::format("the captures span only {:.0f} s", span);
    return {};
  }
  std::string_view CapturePlan() const override {
    return "captures spanning 60 s or more (a pose repeated at the start and the end shows it "
           "best)";
  }
  std::string WhyImplausible(const double* drift, const SensorModel& base,
                             const std::vector<FitCapture>& captures) const override {
    const double span_s = SpreadOfTime(captures);
    const double bound_mps2 = kMaxDriftFractionOfFullScale * kFullScaleMps2;
    for (int j = 0; j < 3; ++j) {
      const double moved_mps2 = std::fabs(drift[j]) * span_s / base.scale_counts_per_mps2(j);
      if (moved_mps2 > bound_mps2)
        return fmt::format("axis {} would move {:.3g} m/s^2 over the {:.0f} s session, beyond "
                           "1 % of a 6 g full scale", kAxes[j], moved_mps2, span_s);
    }
    return {};
  }
  template <class S, class Base>
  void Apply(const S* drift, const Base&, const FitCapture& c, const EffectContext& ctx,
             CorrectedCaptureOf<S>* out) const {
    const double dt_s = c.mean_t_s - ctx.t_ref_s;
    for (int j = 0; j < 3; ++j) out->raw_counts(j) -= drift[j] * dt_s;
  }
  std::string_view RegressorName() const override { return "time"; }
  double Regressor(const FitCapture& c) const override { return c.mean_t_s; }
  int CorrectionStage() const override { return 0; }
  bool CorrectsReadings() const override { return false; }  // a session artifact, see docs/model.md
  std::string_view PlainName() const override { return "a drifting zero-g level"; }
  std::optional<BenchStatement> InBenchTerms(std::span<const double> drift, std::span<const double>,
                                             std::string_view, double) const override {
    return PerAxisStatement("the zero-g level drifts during the session: ", drift, 60.0, 2, "counts per minute");
  }
};

}  // namespace

const Effect& QuadraticNonlinearityEffect() { static const QuadraticNonlinearity e; return e; }
const Effect& CubicNonlinearityEffect() { static const CubicNonlinearity e; return e; }
const Effect& CrossAxisCouplingEffect() { static const CrossAxisCoupling e; return e; }
const Effect& TemperatureBiasEffect() { static const TemperatureBias e; return e; }
const Effect& TemperatureScaleEffect() { static const TemperatureScale e; return e; }
const Effect& BiasDriftEffect() { static const BiasDrift e; return e; }

}  // namespace accelcal::effects
