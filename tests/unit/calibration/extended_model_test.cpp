// The extended model's gradient (extended_model.h), carried through the effects as jets, held to
// derivatives the test takes itself from the residual's values: a five-point central difference
// (error O(h^4)) for every parameter of every effect of the library and of the rivals, alone
// and in pairs, on static and turntable captures with temperatures and times; and the residual
// the same, bit for bit, with derivatives asked for or not.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/calibration/capture_screening.h"
#include "accelcal/calibration/diagnosis/extended_model.h"
#include "accelcal/calibration/diagnosis/rival_explanations.h"
#include "physics_captures.h"

namespace accelcal {
namespace {

std::vector<FitCapture> RichCaptures() {
  const testing::PhysicsSet set = testing::MakePhysicsSet(physgen::Effects{}, 7, /*rich=*/true);
  std::vector<FitCapture> out;
  for (const Capture& c : set.captures) out.push_back(MakeFitCapture(c));
  return out;
}

// A base model near the physics bench's sensor, and every effect parameter at 30 of its scales
// with alternating signs (so that each effect acts, and no two parameters are alike); the tilt's
// loss stays positive.
Eigen::VectorXd ActiveParameters(const ExtendedResidualModel& model) {
  Eigen::VectorXd p(model.NumParameters());
  p.head(kNumBaseParameters) << 2051.0, 2043.0, 2062.0, 34.8, 35.1, 34.3, 2e-3, -1.5e-3, 1e-3;
  for (int i = kNumBaseParameters; i < p.size(); ++i) {
    const double sign = i % 2 == 0 ? 1.0 : -1.0;
    p(i) = 0.0;
    p(i) = 30.0 * model.ParameterScale(p, i) * sign;
    if (model.ParameterLabel(i) == "tilt_loss") p(i) = std::fabs(p(i));
  }
  return p;
}

double FivePointDerivative(const ExtendedResidualModel& model, const Eigen::VectorXd& p, int i,
                           const FitCapture& c, double g) {
  const double h = 0.05 * model.ParameterScale(p, i);
  auto at = [&](double step) {
    Eigen::VectorXd q = p;
    q(i) += step;
    return model.Residual(q, c, g, nullptr, nullptr);
  };
  return (8.0 * (at(h) - at(-h)) - (at(2.0 * h) - at(-2.0 * h))) / (12.0 * h);
}

void ExpectGradientMatchesValues(const std::vector<const Effect*>& effects) {
  const std::vector<FitCapture> captures = RichCaptures();
  const double g = 9.80665;
  const ExtendedResidualModel model(effects, MakeEffectContext(captures, g));
  const Eigen::VectorXd p = ActiveParameters(model);
  int turntable = 0;
  for (const FitCapture& c : captures) {
    turntable += c.kind == CaptureKind::kTurntable;
    Eigen::VectorXd grad;
    const double r = model.Residual(p, c, g, &grad, nullptr);
    ASSERT_EQ(grad.size(), model.NumParameters());
    EXPECT_EQ(r, model.Residual(p, c, g, nullptr, nullptr));
    for (int i = 0; i < model.NumParameters(); ++i) {
      const double numeric = FivePointDerivative(model, p, i, c, g);
      // Relative to the parameter's effect on the residual: a scale's worth of change.
      const double scale = model.ParameterScale(p, i);
      EXPECT_NEAR(grad(i) * scale, numeric * scale, 1e-9 + 1e-6 * std::fabs(numeric * scale))
          << model.ParameterLabel(i) << " on capture " << c.id;
    }
  }
  EXPECT_GT(turntable, 0);
}

TEST(ExtendedModelGradient, MatchesTheResidualForEachEffectOfTheLibrary) {
  for (const Effect* e : AllEffects()) {
    SCOPED_TRACE(std::string(e->Name()));
    ExpectGradientMatchesValues({e});
  }
}

TEST(ExtendedModelGradient, MatchesTheResidualForPairsOfEffects) {
  const std::vector<std::pair<const char*, const char*>> pairs = {
      {"cubic_nonlinearity", "temperature_scale"}, {"quadratic_nonlinearity", "rpm_scale"},
      {"cross_axis_coupling", "size_effect"},      {"bias_drift", "turntable_tilt"},
      {"temperature_bias", "radius_offset"},       {"cubic_nonlinearity", "quadratic_nonlinearity"}};
  for (const auto& [a, b] : pairs) {
    SCOPED_TRACE(std::string(a) + " + " + b);
    ASSERT_NE(FindEffect(a), nullptr);
    ASSERT_NE(FindEffect(b), nullptr);
    ExpectGradientMatchesValues({FindEffect(a), FindEffect(b)});
  }
}

TEST(ExtendedModelGradient, MatchesTheResidualForTheRivals) {
  const std::vector<RivalExplanation> rivals = RivalExplanations(RichCaptures());
  ASSERT_FALSE(rivals.empty());
  for (const RivalExplanation& r : rivals) {
    SCOPED_TRACE(std::string(r.effect->Name()));
    ExpectGradientMatchesValues({r.effect.get()});
  }
}

// An effect with only a value form (no jets): the model falls back to central differences.
class ValueOnlyShift final : public Effect {
 public:
  std::string_view Name() const override { return "value_only_shift"; }
  std::string_view Story() const override { return "a test effect"; }
  int NumParameters() const override { return 1; }
  std::string ParameterName(int) const override { return "s"; }
  std::string ParameterUnit(int) const override { return "1"; }
  double ParameterScale(int, const SensorModel&, const EffectContext&) const override { return 1e-4; }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>&) const override { return {}; }
  std::string_view CapturePlan() const override { return {}; }
  std::string WhyImplausible(const double*, const SensorModel&,
                             const std::vector<FitCapture>&) const override {
    return {};
  }
  void Correct(const double* s, const SensorModel&, const FitCapture&, const EffectContext&,
               CorrectedCapture* out) const override {
    out->raw_counts *= 1.0 + s[0];
  }
  int CorrectionStage() const override { return 1; }
  bool CorrectsReadings() const override { return false; }
};

TEST(ExtendedModelGradient, FallsBackToDifferencesForAnEffectWithoutJets) {
  const ValueOnlyShift shift;
  ExpectGradientMatchesValues({&shift, FindEffect("cubic_nonlinearity")});
}

// The whole library at once has more parameters than a jet has slots (effect_jet.h): central
// differences then, still matching.
TEST(ExtendedModelGradient, FallsBackToDifferencesForMoreParametersThanAJetHolds) {
  int effect_parameters = 0;
  for (const Effect* e : AllEffects()) effect_parameters += e->NumParameters();
  ASSERT_GT(kJetBaseSlots + effect_parameters, kMaxJetParameters);
  ExpectGradientMatchesValues(AllEffects());
}

}  // namespace
}  // namespace accelcal
