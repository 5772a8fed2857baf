// The bench's errors during the calibration (effect.h): where the sensing point really is, how
// fast the table really turns, where each axis's proof mass sits, and how level the spin axis
// is. None of them is a property of later readings: `accelcal apply` does not apply them.
#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/calibration/diagnosis/effect_support.h"

namespace accelcal::effects {
namespace {

constexpr std::string_view kBenchAxisNames = "xyz";
constexpr double kRadToDeg = 180.0 / M_PI;

// Bounds (accelcal's): the sensing point within 2 cm of where the radius was measured (a board
// a few cm across), the table's speed within 5 % of the stated one, each proof mass within 1 cm
// of the nominal sensing point (a package a few mm across), the spin axis within 5 deg of the
// vertical (twice the wizard's leveling tolerance of 2 deg).
constexpr double kMaxRadiusOffsetM = 0.02;
constexpr double kMaxRpmScale = 0.05;
constexpr double kMaxSizeEffectM = 0.01;
constexpr double kMaxTiltDeg = 5.0;

// "<lead>3.0 mm longer<tail> (+-0.2 mm)": the first of `values` and of `sigmas` times `factor`;
// none when the value is not a number.
std::optional<BenchStatement> DirectionStatement(std::string lead, std::span<const double> values,
                                                 std::span<const double> sigmas, double factor, int decimals,
                                                 std::string unit, std::string positive, std::string negative,
                                                 std::string tail) {
  const double value = FirstOf(values);
  if (!std::isfinite(value)) return std::nullopt;
  BenchStatement s{std::move(lead), {}, std::move(tail)};
  s.size.shape = BenchQuantity::Shape::kDirection;
  s.size.values = {value * factor};
  s.size.sigma = FirstOf(sigmas) * factor;
  s.size.unit = std::move(unit);
  s.size.decimals = decimals;
  s.size.positive = std::move(positive);
  s.size.negative = std::move(negative);
  return s;
}

double SmallestRadius(const std::vector<FitCapture>& captures) {
  double smallest = INFINITY;
  for (const FitCapture& c : captures)
    if (c.kind == CaptureKind::kTurntable) smallest = std::min(smallest, c.radius_m);
  return smallest;
}

// What the bench's errors share: they act on the turntable runs' reference and grow with w^2 r,
// correct at the last stage (the bench's geometry), never later readings, and the advice is to
// correct the bench and refit.
template <class Derived>
class BenchError : public DifferentiableEffect<Derived> {
 public:
  std::string_view RegressorName() const override { return "w^2 r"; }
  double Regressor(const FitCapture& c) const override { return CentripetalMps2(c); }
  int CorrectionStage() const override { return 3; }
  bool CorrectsReadings() const override { return false; }
  bool IsBenchError() const override { return true; }
};

// --- radius_offset ---------------------------------------------------------------------------
class RadiusOffset final : public BenchError<RadiusOffset> {
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
  std::string_view CapturePlan() const override { return "turntable captures at two radii or more"; }
  std::string WhyImplausible(const double* dr, const SensorModel&,
                             const std::vector<FitCapture>& captures) const override {
    if (std::fabs(dr[0]) > kMaxRadiusOffsetM)
      return fmt::format("the sensing point would be {:.1f} mm from where the radius was "
                         "measured, beyond {:.0f} mm", 1000.0 * dr[0], 1000.0 * kMaxRadiusOffsetM);
    if (SmallestRadius(captures) + dr[0] <= 0.0)
      return "the smallest radius would be negative";
    return {};
  }
  template <class S, class Base>
  void Apply(const S* dr, const Base&, const FitCapture& c, const EffectContext&,
             CorrectedCaptureOf<S>* out) const {
    if (c.kind == CaptureKind::kTurntable) out->radius_m += dr[0];
  }
  std::string_view PlainName() const override { return "a wrong turntable radius"; }
  bool TakesGravityErrorForItsOwn() const override { return true; }
  std::optional<VerifyingEquipment> VerifiedBy() const override {
    return VerifyingEquipment{"ruler", "radius", "a calibrated ruler"};
  }
  std::optional<BenchStatement> InBenchTerms(std::span<const double> dr, std::span<const double> sigma,
                                             std::string_view, double) const override {
    return DirectionStatement("the turntable radius seems ", dr, sigma, 1000.0, 1, "mm", "longer", "shorter",
                              " than entered");
  }
};

// --- rpm_scale -------------------------------------------------------------------------------
class RpmScale final : public BenchError<RpmScale> {
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
  std::string_view CapturePlan() const override { return "two turntable captures or more"; }
  std::string WhyImplausible(const double* s, const SensorModel&,
                             const std::vector<FitCapture>&) const override {
    if (std::fabs(s[0]) > kMaxRpmScale)
      return fmt::format("the table would turn {:+.1f} % off the stated speed, beyond {:.0f} %",
                         100.0 * s[0], 100.0 * kMaxRpmScale);
    return {};
  }
  template <class S, class Base>
  void Apply(const S* s, const Base&, const FitCapture& c, const EffectContext&,
             CorrectedCaptureOf<S>* out) const {
    if (c.kind == CaptureKind::kTurntable) out->omega_rad_per_s *= 1.0 + s[0];
  }
  std::string_view PlainName() const override { return "a wrong table speed"; }
  bool TakesGravityErrorForItsOwn() const override { return true; }
  std::optional<VerifyingEquipment> VerifiedBy() const override {
    return VerifyingEquipment{"turntable", "speed", "a calibrated tachometer"};
  }
  std::optional<BenchStatement> InBenchTerms(std::span<const double> s, std::span<const double> sigma,
                                             std::string_view, double) const override {
    return DirectionStatement("the turntable seems to turn ", s, sigma, 100.0, 2, "%", "faster", "slower",
                              " than entered");
  }
};

// --- size_effect -----------------------------------------------------------------------------
// Each axis's proof mass sits d_j along its own axis from the nominal sensing point; an axis in
// the table's plane then feels the centripetal acceleration of its own radius: -w^2 d_j extra
// along itself (radial or tangential alike); the vertical axis feels none.
class SizeEffect final : public BenchError<SizeEffect> {
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
      if (!in_plane[j]) return fmt::format("axis {} never lies in the table's plane", kBenchAxisNames[j]);
    return {};
  }
  std::string_view CapturePlan() const override {
    return "the mounting (up_axis) of three turntable captures or more, every axis in the "
           "table's plane at least once";
  }
  std::string WhyImplausible(const double* d, const SensorModel&,
                             const std::vector<FitCapture>&) const override {
    for (int j = 0; j < 3; ++j)
      if (std::fabs(d[j]) > kMaxSizeEffectM)
        return fmt::format("axis {}'s proof mass would sit {:.1f} mm from the sensing point, "
                           "beyond {:.0f} mm", kBenchAxisNames[j], 1000.0 * d[j], 1000.0 * kMaxSizeEffectM);
    return {};
  }
  template <class S, class Base>
  void Apply(const S* d, const Base& base, const FitCapture& c, const EffectContext&,
             CorrectedCaptureOf<S>* out) const {
    if (c.kind != CaptureKind::kTurntable || !c.up_axis) return;
    const Eigen::Vector3d up = SensorAxisVector(*c.up_axis);
    const S w2 = out->omega_rad_per_s * out->omega_rad_per_s;
    for (int j = 0; j < 3; ++j) {
      const double in_plane = 1.0 - up(j) * up(j);
      out->raw_counts(j) += base.scale_counts_per_mps2(j) * w2 * d[j] * in_plane;
    }
  }
  std::string_view PlainName() const override { return "the sensor's size"; }
  std::optional<BenchStatement> InBenchTerms(std::span<const double> d, std::span<const double>, std::string_view,
                                             double) const override {
    return PerAxisStatement("each axis senses at a point off the one the radius was measured to: ", d, 1000.0, 1,
                            "mm");
  }
};

// --- turntable_tilt --------------------------------------------------------------------------
// A spin axis tilted by theta from the vertical: gravity's part along it is g cos(theta), and
// its part in the table's plane, g sin(theta), turns once per revolution in the sensor frame, so
// it averages out of a capture's mean over whole revolutions. The mean then shows
// |f| = sqrt((g cos theta)^2 + (w^2 r)^2). The parameter is 1 - cos(theta) (a tilt is felt in
// its square, so theta itself would be a poor parameter near zero), never negative.
class TurntableTilt final : public BenchError<TurntableTilt> {
 public:
  std::string_view Name() const override { return "turntable_tilt"; }
  std::string_view Story() const override {
    return "the turntable's spin axis is not vertical: its runs feel only g cos(tilt) along the "
           "axis, the rest of gravity turning once per revolution";
  }
  int NumParameters() const override { return 1; }
  std::string ParameterName(int) const override { return "tilt_loss"; }
  std::string ParameterUnit(int) const override { return "1"; }
  double ParameterScale(int, const SensorModel&, const EffectContext&) const override { return 1e-4; }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    const int turntable = CountTurntable(captures);
    if (turntable < 2) return "needs two turntable captures or more";
    if (static_cast<int>(captures.size()) - turntable < 3)
      return "needs static poses beside the turntable runs (a tilt lowers only the runs' reference)";
    return {};
  }
  std::string_view CapturePlan() const override {
    return "two turntable captures or more beside static poses, each run over whole revolutions";
  }
  std::string WhyImplausible(const double* loss, const SensorModel&,
                             const std::vector<FitCapture>&) const override {
    if (loss[0] < 0.0)
      return "the runs read as if gravity along the spin axis exceeded g, which no tilt can do";
    const double tilt_deg = std::acos(std::max(-1.0, 1.0 - loss[0])) * kRadToDeg;
    if (tilt_deg > kMaxTiltDeg)
      return fmt::format("the table would be tilted {:.1f} deg, beyond {:.0f} deg", tilt_deg, kMaxTiltDeg);
    return {};
  }
  std::string Interpretation(const double* loss) const override {
    if (!(loss[0] >= 0.0)) return {};
    return fmt::format("a spin axis tilted {:.2f} deg from the vertical",
                       std::acos(std::max(-1.0, 1.0 - loss[0])) * kRadToDeg);
  }
  template <class S, class Base>
  void Apply(const S* loss, const Base&, const FitCapture& c, const EffectContext&,
             CorrectedCaptureOf<S>* out) const {
    if (c.kind == CaptureKind::kTurntable) out->gravity_along_axis *= 1.0 - loss[0];
  }
  std::string_view PlainName() const override { return "a tilted turntable"; }
  std::optional<BenchStatement> InBenchTerms(std::span<const double>, std::span<const double>,
                                             std::string_view interpretation, double) const override {
    std::string lead = "the turntable's spin axis is not vertical";
    if (!interpretation.empty()) lead += ": " + std::string(interpretation);
    // Member by member: GCC 12 at -O3 (the Release build) takes the braced form's empty size for
    // an uninitialised string (a false -Wmaybe-uninitialized, an error under -Werror).
    BenchStatement statement;
    statement.lead = std::move(lead);
    statement.tail = "; level the turntable";
    return statement;
  }
};

}  // namespace

const Effect& RadiusOffsetEffect() { static const RadiusOffset e; return e; }
const Effect& RpmScaleEffect() { static const RpmScale e; return e; }
const Effect& SizeEffectEffect() { static const SizeEffect e; return e; }
const Effect& TurntableTiltEffect() { static const TurntableTilt e; return e; }

}  // namespace accelcal::effects
