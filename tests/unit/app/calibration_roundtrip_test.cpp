// Issue 13 item 1: every number in the calibration file comes from the final model. Each written
// calibration (through its JSON text), applied by CalibrationApplier to its own captures' mean
// readings, must give back the residual the fit reported for every capture: each effect alone
// and in pairs, on capture sets of the independent physics bench (physics_captures.h).
//
// `apply` corrects the sensor's own effects only; the bench's effects of the session are added
// here from docs/model.md's definitions, written again: the session's bias drift is taken off the
// mean reading; the size effect gives axis j in the table's plane back w^2 d_j of a^a
// (a^a = T^-1 a^p); the reference is |f| = sqrt((g (1 - tilt_loss))^2 + (w^2 (r + dr))^2) with
// w = (1 + rpm_scale) rpm 2 pi / 60.
#include <cmath>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "accelcal/app/calibration_pipeline.h"
#include "accelcal/calibration/apply.h"
#include "accelcal/io/calibration_file.h"
#include "physics_captures.h"

namespace accelcal {
namespace {

double Param(const Calibration& cal, const char* effect, const std::string& name) {
  const CalibrationEffect* e = cal.FindEffect(effect);
  if (e == nullptr) return 0.0;
  const EffectParameter* p = e->Find(name);
  return p != nullptr ? p->value : kNaN;
}

Eigen::Vector3d Triple(const Calibration& cal, const char* effect, const char* stem) {
  return {Param(cal, effect, std::string(stem) + "_x"), Param(cal, effect, std::string(stem) + "_y"),
          Param(cal, effect, std::string(stem) + "_z")};
}

// |a| - |f| of `capture` as the header says, from the calibration alone.
double AppliedResidual(const Calibration& cal, const CalibrationApplier& applier, const Capture& capture) {
  const CaptureStats& stats = capture.stats();
  Sample mean;
  mean.t_s = stats.mean_t_s;
  mean.temp_c = stats.mean_temp_c;
  mean.raw_counts = stats.mean_counts - Triple(cal, "bias_drift", "drift") * (stats.mean_t_s - cal.reference.t_s);
  Eigen::Vector3d a = applier.Apply(mean);
  if (capture.kind == CaptureKind::kStatic) return a.norm() - cal.gravity.gravity_mps2;
  const double w = (1.0 + Param(cal, "rpm_scale", "rpm_scale")) * capture.rpm * 2.0 * M_PI / 60.0;
  const Eigen::Matrix3d t = cal.model.Misalignment();
  Eigen::Vector3d u = t.inverse() * a;
  const Eigen::Vector3d up = SensorAxisVector(*capture.up_axis);
  const Eigen::Vector3d d = Triple(cal, "size_effect", "d");
  for (int j = 0; j < 3; ++j) u(j) += w * w * d(j) * (1.0 - up(j) * up(j));
  a = t * u;
  return a.norm() - std::hypot(cal.gravity.gravity_mps2 * (1.0 - Param(cal, "turntable_tilt", "tilt_loss")),
                               w * w * (capture.radius_m + Param(cal, "radius_offset", "dr")));
}

struct RoundTripCase {
  const char* name;
  unsigned long long seed;
  double turntable_s;
  void (*inject)(physgen::Effects*);
  std::vector<std::string> expected;  // the effects the calibration must hold, in any order
};

class WrittenCalibration : public ::testing::TestWithParam<RoundTripCase> {};

TEST_P(WrittenCalibration, AppliedToItsOwnCapturesGivesTheFitsResidualsBack) {
  const RoundTripCase& c = GetParam();
  physgen::Effects effects;
  c.inject(&effects);
  const testing::PhysicsSet set = testing::MakePhysicsSet(effects, c.seed, false, c.turntable_s);
  CalibrationRequest request;
  request.captures = set.captures;
  request.source_name = c.name;
  request.screening.adc_range = AdcRange{0, 4095};
  request.diagnosis.leave_one_out = false;  // the ranking by BIC suffices here, and is fast
  const CalibrationOutcome outcome = CalibrateCaptures(std::move(request));
  ASSERT_TRUE(outcome.usable()) << outcome.diagnosis.base.message;
  const Calibration written = outcome.MakeCalibration(true);
  for (const std::string& name : c.expected)
    ASSERT_NE(written.FindEffect(name), nullptr) << name << " not adopted\n" << FormatDiagnosis(outcome.diagnosis);
  ASSERT_EQ(written.effects.size(), c.expected.size()) << FormatDiagnosis(outcome.diagnosis);

  const Calibration cal = CalibrationFromJsonText(CalibrationToJsonText(written), "cal.json");
  const CalibrationApplier applier(cal);
  int compared = 0;
  for (size_t i = 0; i < cal.captures.size(); ++i) {
    if (!cal.captures[i].used) continue;
    const double applied = AppliedResidual(cal, applier, outcome.captures[i]);
    EXPECT_NEAR(applied, cal.captures[i].residual_mps2, 1e-9)
        << c.name << " capture " << cal.captures[i].id << "\n" << FormatDiagnosis(outcome.diagnosis);
    ++compared;
  }
  EXPECT_GE(compared, 17);
}

// Pairs with a temperature effect use seed 2: on seed 1 the standard plan cannot tell a
// temperature warm-up from a drift in time (their BICs within 2; the diagnosis says so and
// adopts neither), and this test is about what the file holds once the effects are adopted.
const RoundTripCase kCases[] = {
    {"quadratic", 1, 10, [](physgen::Effects* e) { e->quadratic = {0.02, -0.015, 0.01}; }, {"quadratic_nonlinearity"}},
    {"temperature_bias", 1, 10, [](physgen::Effects* e) { e->temp_bias = {0.5, -0.3, 0.8}; }, {"temperature_bias"}},
    {"radius_offset", 1, 10, [](physgen::Effects* e) { e->radius_offset_m = 0.003; }, {"radius_offset"}},
    {"size_effect", 1, 10, [](physgen::Effects* e) { e->size_effect_m = {0.0015, -0.001, 0.002}; }, {"size_effect"}},
    {"cubic", 1, 10, [](physgen::Effects* e) { e->cubic = {1e-4, 0.0, 0.0}; }, {"cubic_nonlinearity"}},
    {"tilt", 1, 300, [](physgen::Effects* e) { e->tilt_rad = 2.0 * M_PI / 180.0; }, {"turntable_tilt"}},
    {"quadratic_and_temperature_bias", 2, 10,
     [](physgen::Effects* e) { e->quadratic = {0.02, -0.015, 0.01}; e->temp_bias = {0.5, -0.3, 0.8}; },
     {"quadratic_nonlinearity", "temperature_bias"}},
    {"radius_and_size", 1, 10,
     [](physgen::Effects* e) { e->radius_offset_m = 0.003; e->size_effect_m = {0.0015, -0.001, 0.002}; },
     {"radius_offset", "size_effect"}},
    // A temperature scale and a drift together: no seed of 1..5 has the standard plan tell the
    // drift from a temperature bias (see above); the drift alone on seed 2 instead.
    {"bias_drift", 2, 10, [](physgen::Effects* e) { e->drift = {0.002, 0.0, -0.001}; }, {"bias_drift"}},
    {"cross_and_rpm", 1, 10,
     [](physgen::Effects* e) { e->cross_x_yz = 0.03; e->rpm_scale = 0.01; },
     {"cross_axis_coupling", "rpm_scale"}},
};

INSTANTIATE_TEST_SUITE_P(EachEffectAndPairs, WrittenCalibration, ::testing::ValuesIn(kCases),
                         [](const auto& test_info) { return std::string(test_info.param.name); });

// The case of the issue: radius offset and size effect on the standard plan. The file once said
// d = (4.64, 2.01, 5.10) +- 0.14 mm for a truth of (1.5, -1.0, 2.0) mm: the parameters of the
// round that adopted the size effect, before the radius offset moved them.
TEST(WrittenCalibration, RadiusAndSizeEffectMatchTheTruth) {
  physgen::Effects effects;
  effects.radius_offset_m = 0.003;
  effects.size_effect_m = {0.0015, -0.001, 0.002};
  const testing::PhysicsSet set = testing::MakePhysicsSet(effects, 1);
  CalibrationRequest request;
  request.captures = set.captures;
  request.screening.adc_range = AdcRange{0, 4095};
  const CalibrationOutcome outcome = CalibrateCaptures(std::move(request));
  ASSERT_TRUE(outcome.usable());
  const Calibration cal =
      CalibrationFromJsonText(CalibrationToJsonText(outcome.MakeCalibration(true)), "cal.json");
  const CalibrationEffect* radius = cal.FindEffect("radius_offset");
  const CalibrationEffect* size = cal.FindEffect("size_effect");
  ASSERT_TRUE(radius != nullptr && size != nullptr) << FormatDiagnosis(outcome.diagnosis);
  EXPECT_NEAR(radius->Find("dr")->value, 0.003, 3 * radius->Find("dr")->sigma);
  for (int j = 0; j < 3; ++j) {
    const EffectParameter* d = size->Find(std::string("d_") + "xyz"[j]);
    EXPECT_NEAR(d->value, effects.size_effect_m(j), 3 * d->sigma) << d->name;
  }
}

}  // namespace
}  // namespace accelcal

namespace accelcal {
namespace {

// Issue 13, the quadratic + temperature bias pair on seed 1: the standard plan cannot tell the
// temperature warm-up from a drift in time (BIC within 2), and that ambiguity once withdrew the
// quadratic nonlinearity adopted the round before, so the base model's chi2/dof (2150) went past
// the refusal limit and the fit was refused as "captures that disagree". The quadratic stays,
// both candidates for the rest are named, and the file holds the quadratic as fitted.
TEST(WrittenCalibration, AnAmbiguousRestKeepsTheEffectAdoptedBefore) {
  physgen::Effects effects;
  effects.quadratic = {0.02, -0.015, 0.01};
  effects.temp_bias = {0.5, -0.3, 0.8};
  const testing::PhysicsSet set = testing::MakePhysicsSet(effects, 1);
  CalibrationRequest request;
  request.captures = set.captures;
  request.screening.adc_range = AdcRange{0, 4095};
  const CalibrationOutcome outcome = CalibrateCaptures(std::move(request));
  ASSERT_TRUE(outcome.usable()) << outcome.diagnosis.conclusion;
  const DiagnosisReport& d = outcome.diagnosis;
  EXPECT_EQ(d.adopted_names(), std::vector<std::string>{"quadratic_nonlinearity"}) << FormatDiagnosis(d);
  EXPECT_TRUE(d.unexplained);
  ASSERT_EQ(d.ambiguous.size(), 2u) << FormatDiagnosis(d);
  EXPECT_NE(d.conclusion.find("cannot tell them apart"), std::string::npos) << d.conclusion;
  EXPECT_NE(d.conclusion.find("temperature"), std::string::npos) << d.conclusion;
  const Calibration cal =
      CalibrationFromJsonText(CalibrationToJsonText(outcome.MakeCalibration(true)), "cal.json");
  const CalibrationEffect* q = cal.FindEffect("quadratic_nonlinearity");
  ASSERT_TRUE(q != nullptr);
  for (int j = 0; j < 3; ++j) {
    const EffectParameter* p = q->Find(std::string("q_") + "xyz"[j]);
    ASSERT_TRUE(p != nullptr);
    EXPECT_NEAR(p->value, effects.quadratic(j), 3 * p->sigma) << p->name;
  }
}

}  // namespace
}  // namespace accelcal
