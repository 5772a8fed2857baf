// An effect owns what is said and written of it (issue 28): an effect defined only here, and
// registered from here (EffectRegistration), is read, put in words, reported and exported from
// what it declares, with no other file knowing its name.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/io/export/c_header.h"
#include "export_test_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

// The zero-g level settling after power-up: b_j + a_j exp(-t / 300 s). A property of the sensor
// (apply corrects readings with it), but accelcal_correct in the C header is not given the time
// since power-up: the header cannot carry it, and says so.
class WarmupBias final : public DifferentiableEffect<WarmupBias> {
 public:
  std::string_view Name() const override { return "warmup_bias"; }
  std::string_view Story() const override { return "the zero-g level settles after power-up"; }
  int NumParameters() const override { return 3; }
  std::string ParameterName(int i) const override { return std::string("warmup_") + "xyz"[i]; }
  std::string ParameterUnit(int) const override { return "counts"; }
  double ParameterScale(int, const SensorModel&, const EffectContext&) const override { return 1e-2; }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>&) const override { return {}; }
  std::string_view CapturePlan() const override { return "captures from power-up on"; }
  std::string WhyImplausible(const double*, const SensorModel&, const std::vector<FitCapture>&) const override {
    return {};
  }
  template <class S, class Base>
  void Apply(const S* a, const Base&, const FitCapture& c, const EffectContext&, CorrectedCaptureOf<S>* out) const {
    for (int j = 0; j < 3; ++j) out->raw_counts(j) -= a[j] * std::exp(-c.mean_t_s / 300.0);
  }
  int CorrectionStage() const override { return 0; }
  bool CorrectsReadings() const override { return true; }
};

CalibrationEffect Adopted(const Effect& effect, const std::vector<double>& values) {
  CalibrationEffect e;
  e.name = std::string(effect.Name());
  for (int i = 0; i < effect.NumParameters(); ++i)
    e.parameters.push_back({effect.ParameterName(i), effect.ParameterUnit(i), values[static_cast<size_t>(i)], kNaN});
  e.corrects_readings = effect.CorrectsReadings();
  return e;
}

// The defect of issue 28: the C header wrote any sensor effect it did not know as the quadratic
// nonlinearity (here a second time, beside the real one: the header compiled and corrected
// readings wrongly, silently). It must refuse the effect by name.
TEST(EffectOwnership, TheCHeaderRefusesBYNameASensorEffectItCannotCarry) {
  const WarmupBias warmup;
  const EffectRegistration registered(warmup);
  Calibration cal = testing::ExportTestCalibrationWithEffects();
  cal.effects.push_back(Adopted(warmup, {1.5, -0.5, 0.25}));
  try {
    const std::string header = ExportCHeader(cal, {}).text;
    FAIL() << "exported:\n" << header;
  } catch (const Error& e) {
    EXPECT_TRUE(testing::Contains(e.what(), "'warmup_bias'")) << e.what();
    EXPECT_TRUE(testing::Contains(e.what(), "C header cannot carry")) << e.what();
  }
}

TEST(EffectOwnership, ARegistrationEndsWithItsLifeAndRefusesATakenName) {
  {
    const WarmupBias warmup;
    const EffectRegistration registered(warmup);
    EXPECT_EQ(FindEffect("warmup_bias"), &warmup);
    EXPECT_THROW(EffectRegistration again(warmup), Error);
  }
  EXPECT_EQ(FindEffect("warmup_bias"), nullptr);
  EXPECT_EQ(KnownEffects().size(), AllEffects().size());
}

}  // namespace
}  // namespace accelcal
