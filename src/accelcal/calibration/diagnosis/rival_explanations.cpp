#include "accelcal/calibration/diagnosis/rival_explanations.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/calibration/diagnosis/effect_support.h"

namespace accelcal {
namespace {

constexpr std::string_view kTurntableShiftName = "turntable_bias_shift";
constexpr std::string_view kScaleAsymmetryName = "scale_asymmetry";

// A bias offset the size of which no bench sensor shows between two captures: 1 % of a 6 g full
// scale, the bound the drift effect uses (effect_support.h).
std::string RivalShiftBeyondBound(const double* shift_counts, const SensorModel& base) {
  const double bound_mps2 = 0.01 * effects::kFullScaleMps2;
  for (int j = 0; j < 3; ++j)
    if (std::fabs(shift_counts[j]) / base.scale_counts_per_mps2(j) > bound_mps2)
      return fmt::format("a shift of {:.3g} counts on axis {}", shift_counts[j], "xyz"[j]);
  return {};
}

// A bias offset: three offsets in counts, applied to the captures `Applies` picks.
template <class Derived>
class RivalBiasOffset : public DifferentiableEffect<Derived> {
 public:
  int NumParameters() const override { return 3; }
  std::string ParameterName(int i) const override { return effects::PerAxis("shift", i); }
  std::string ParameterUnit(int) const override { return "counts"; }
  double ParameterScale(int i, const SensorModel& base, const EffectContext&) const override {
    return base.scale_counts_per_mps2(i) * 1e-3;  // 1e-3 m/s^2 of bias
  }
  std::string WhyImplausible(const double* theta, const SensorModel& base,
                             const std::vector<FitCapture>&) const override {
    return RivalShiftBeyondBound(theta, base);
  }
  template <class S, class Base>
  void Apply(const S* theta, const Base&, const FitCapture& c, const EffectContext&,
             CorrectedCaptureOf<S>* out) const {
    if (Applies(c))
      for (int j = 0; j < 3; ++j) out->raw_counts(j) -= theta[j];
  }
  int CorrectionStage() const override { return 0; }
  bool CorrectsReadings() const override { return false; }

 protected:
  virtual bool Applies(const FitCapture& c) const = 0;
};

// A bias that differs while the table turns (vibration rectification, a cable pulled by the
// rotation, the sensor's own heating by the motor).
class RivalTurntableShift final : public RivalBiasOffset<RivalTurntableShift> {
 public:
  std::string_view Name() const override { return kTurntableShiftName; }
  std::string_view Story() const override { return "the bias shifts while the table turns"; }
  std::string_view PlainName() const override { return "a zero-g level that shifts while the table turns"; }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    const int turning = effects::CountTurntable(captures);
    const int still = static_cast<int>(captures.size()) - turning;
    if (turning < 3 || still < 3) return "needs three or more turntable and static captures";
    return {};
  }
  std::string_view CapturePlan() const override { return {}; }

 private:
  bool Applies(const FitCapture& c) const override { return c.kind == CaptureKind::kTurntable; }
};

// raw_j = b_j + k_j u_j + d_j |u_j|: the scale for negative inputs is k_j - d_j, for positive
// ones k_j + d_j (a scale-factor asymmetry).
class RivalScaleAsymmetry final : public DifferentiableEffect<RivalScaleAsymmetry> {
 public:
  std::string_view Name() const override { return kScaleAsymmetryName; }
  std::string_view Story() const override {
    return "each axis has a different scale for positive and negative inputs";
  }
  std::string_view PlainName() const override { return "a sensitivity that differs for up and down"; }
  int NumParameters() const override { return 3; }
  std::string ParameterName(int i) const override { return effects::PerAxis("asym", i); }
  std::string ParameterUnit(int) const override { return "counts/(m/s^2)"; }
  double ParameterScale(int i, const SensorModel& base, const EffectContext&) const override {
    return base.scale_counts_per_mps2(i) * 1e-4;  // ~1e-3 m/s^2 at 10 m/s^2
  }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const override {
    for (int j = 0; j < 3; ++j)
      if (!effects::SeesLevelsFor(captures, j, 2)) return "an axis sees too few input levels";
    return {};
  }
  std::string_view CapturePlan() const override { return {}; }
  std::string WhyImplausible(const double* d, const SensorModel& base,
                             const std::vector<FitCapture>&) const override {
    for (int j = 0; j < 3; ++j)
      if (std::fabs(d[j]) > 0.02 * base.scale_counts_per_mps2(j))  // 2 % of the scale
        return fmt::format("an asymmetry of {:.3g} counts/(m/s^2) on axis {}", d[j], "xyz"[j]);
    return {};
  }
  template <class S, class Base>
  void Apply(const S* d, const Base& base, const FitCapture&, const EffectContext&,
             CorrectedCaptureOf<S>* out) const {
    for (int j = 0; j < 3; ++j) {
      const S k = base.scale_counts_per_mps2(j);
      const S offset = out->raw_counts(j) - base.bias_counts(j);
      // k u + d |u| = offset: u has the sign of offset while |d| < k.
      S slope = k - d[j];
      if (offset >= 0.0) slope = k + d[j];
      S u = offset / k;
      if (std::fabs(ValueOf(slope)) > 0.1 * std::fabs(ValueOf(k))) u = offset / slope;
      out->raw_counts(j) = base.bias_counts(j) + k * u;
    }
  }
  int CorrectionStage() const override { return 2; }
  bool CorrectsReadings() const override { return false; }
};

}  // namespace

std::vector<RivalExplanation> RivalExplanations(const std::vector<FitCapture>& captures) {
  std::vector<RivalExplanation> rivals;
  auto add = [&](std::unique_ptr<Effect> e, int scanned) {
    if (e->WhyNotIdentifiable(captures).empty()) rivals.push_back({std::move(e), scanned});
  };
  add(std::make_unique<RivalTurntableShift>(), 0);
  add(std::make_unique<RivalScaleAsymmetry>(), 0);
  return rivals;
}

const Effect* FindRival(std::string_view name) {
  static const RivalTurntableShift turntable_shift;
  static const RivalScaleAsymmetry scale_asymmetry;
  for (const Effect* rival : {static_cast<const Effect*>(&turntable_shift), static_cast<const Effect*>(&scale_asymmetry)})
    if (rival->Name() == name) return rival;
  return nullptr;
}

std::string RivalStory(const std::string& name) {
  if (name == kTurntableShiftName) return "a bias that shifts while the table turns";
  if (name == kScaleAsymmetryName) return "a scale that differs for positive and negative inputs";
  return {};
}

std::string RivalCapturePlan(const std::string& name) {
  if (name == kTurntableShiftName)
    return "take a static pose again between the turntable runs and after the last one (a bias "
           "that shifts while turning returns when the table stops; a drift or a warm-up does not)";
  if (name == kScaleAsymmetryName)
    return "add tilted poses with each axis pointing down as well as up, at two or more angles, "
           "and turntable runs with the axis outward and inward";
  return {};
}

}  // namespace accelcal
