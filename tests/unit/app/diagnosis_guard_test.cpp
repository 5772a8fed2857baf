// Issue 13 item 2: the three effects added to the library (cubic nonlinearity, cross-axis
// coupling, turntable tilt) are named and recovered, and effects the library does not have are
// not blamed on one that it has: the guard (diagnosis.h, step 3 and 4) keeps the base model and
// says what to capture next. Capture sets from the independent physics bench
// (physics_captures.h); the many-seed figures are in tests/physics/README.md.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "accelcal/acquire/capture_engine/offline_stability.h"
#include "accelcal/app/calibration_pipeline.h"
#include "accelcal/calibration/capture_screening.h"
#include "accelcal/calibration/diagnosis/diagnosis.h"
#include "accelcal/calibration/diagnosis/leave_one_out.h"
#include "accelcal/calibration/diagnosis/residual_structure.h"
#include "accelcal/calibration/diagnosis/rival_explanations.h"
#include "physics_captures.h"
#include "test_support.h"

namespace accelcal {
namespace {

std::vector<FitCapture> FitCaptures(const testing::PhysicsSet& set) {
  std::vector<Capture> captures = set.captures;
  ScreeningOptions screening;
  screening.adc_range = AdcRange{0, 4095};
  ScreenCaptures(captures, screening);
  std::vector<FitCapture> out;
  for (const Capture& c : captures)
    if (c.used()) out.push_back(MakeFitCapture(c));
  return out;
}

DiagnosisReport DiagnosePhysics(const physgen::Effects& effects, unsigned long long seed,
                                double turntable_s = 10.0) {
  const testing::PhysicsSet set = testing::MakePhysicsSet(effects, seed, false, turntable_s);
  return Diagnose(FitCaptures(set), FitOptions{}, DiagnosisOptions{});
}

TEST(NewEffects, CubicNonlinearityIsNamedAndRecovered) {
  physgen::Effects e;
  e.cubic = {1e-4, 0.0, 0.0};
  const DiagnosisReport r = DiagnosePhysics(e, 3);
  ASSERT_EQ(r.adopted_names(), std::vector<std::string>{"cubic_nonlinearity"}) << FormatDiagnosis(r);
  const AdoptedEffect& a = r.adopted.front();
  for (int j = 0; j < 3; ++j)
    EXPECT_NEAR(a.parameters[j], e.cubic(j), 3.5 * a.uncertainty[j]) << a.parameter_names[j];
  EXPECT_TRUE(r.consistent) << FormatDiagnosis(r);
}

TEST(NewEffects, CrossAxisCouplingIsNamedAndItsMagnitudeSumRecovered) {
  physgen::Effects e;
  e.cross_x_yz = 0.03;
  const testing::PhysicsSet set = testing::MakePhysicsSet(e, 3);
  const DiagnosisReport r = Diagnose(FitCaptures(set), FitOptions{}, DiagnosisOptions{});
  ASSERT_EQ(r.adopted_names(), std::vector<std::string>{"cross_axis_coupling"}) << FormatDiagnosis(r);
  // What a magnitude fit sees: kappa = c_x / k_x (tests/physics/physics_bench.h).
  const double kappa = 0.03 / set.data.sensor.scale_counts_per_mps2.x();
  EXPECT_NEAR(r.adopted.front().parameters[0], kappa, 3.5 * r.adopted.front().uncertainty[0]);
}

TEST(NewEffects, TurntableTiltIsNamedAndTheTiltRecovered) {
  physgen::Effects e;
  e.tilt_rad = 2.0 * M_PI / 180.0;
  const DiagnosisReport r = DiagnosePhysics(e, 3, /*turntable_s=*/300.0);
  ASSERT_EQ(r.adopted_names(), std::vector<std::string>{"turntable_tilt"}) << FormatDiagnosis(r);
  const AdoptedEffect& a = r.adopted.front();
  EXPECT_NEAR(a.parameters[0], 1.0 - std::cos(e.tilt_rad), 3.5 * a.uncertainty[0]);
  EXPECT_TRUE(testing::Contains(a.interpretation, "tilted")) << a.interpretation;
}

struct Outside {
  const char* name;
  void (*inject)(physgen::Effects*);
};

class OutsideTheLibrary : public ::testing::TestWithParam<Outside> {};

// The base model is kept, the conclusion says so in the words, and what to capture next
// is said. A regression test of that path on fixed seeds; the many-seed rates are in
// tests/physics/README.md (with the rival explanations: asym_scale, bias_jump and
// turntable_bias each 0/50).
TEST_P(OutsideTheLibrary, NoEffectIsBlamedAndTheNextCapturesAreNamed) {
  physgen::Effects e;
  GetParam().inject(&e);
  for (unsigned long long seed : {1ull, 2ull}) {
    const DiagnosisReport r = DiagnosePhysics(e, seed);
    EXPECT_TRUE(r.adopted.empty()) << "seed " << seed << "\n" << FormatDiagnosis(r);
    EXPECT_TRUE(r.unexplained) << FormatDiagnosis(r);
    EXPECT_TRUE(testing::Contains(r.conclusion, "the residuals exceed noise and no effect of the "
                                                "library explains them")) << r.conclusion;
    EXPECT_FALSE(r.next_captures.empty());
    EXPECT_EQ(r.final_fit.parameters, r.base.parameters);
  }
}

// Through the whole pipeline, as `accelcal fit` runs it: the capture an effect outside the library
// leaves predicted worst is not left out to make room for a library effect. Before, the
// pipeline's disagreement step (app/disagreeing_captures.h) left out -x up (asymmetric scale on
// x) or a turntable run, and the diagnosis of the rest adopted size_effect or
// quadratic_nonlinearity (chi2/dof about 1.6 on 5 degrees of freedom): 47 of 50 seeds of the CLI.
TEST(Guard, ACaptureIsNotLeftOutToMakeRoomForANewEffect) {
  physgen::Effects e;
  e.asym_scale = {0.003, 0.0, 0.0};
  for (unsigned long long seed : {1ull, 2ull, 3ull}) {
    CalibrationRequest request;
    request.captures = testing::MakePhysicsSet(e, seed).captures;
    request.source_name = "physics";
    request.screening.adc_range = AdcRange{0, 4095};
    request.stability = OfflineStabilityOptions{};
    const CalibrationOutcome o = CalibrateCaptures(std::move(request));
    ASSERT_TRUE(o.usable()) << o.diagnosis.base.message;
    EXPECT_TRUE(o.diagnosis.adopted.empty()) << "seed " << seed << "\n" << FormatDiagnosis(o.diagnosis);
    for (const Capture& c : o.captures) EXPECT_TRUE(c.used()) << "seed " << seed << ": " << c.rejection_reason;
    EXPECT_TRUE(testing::Contains(o.diagnosis.conclusion, "no effect of the library explains them"))
        << o.diagnosis.conclusion;
  }
}

// The rival explanations (rival_explanations.h): a bias that shifts while the table turns is
// explained about as well by a warm-up or a drift, because every turntable run follows every
// static pose on the seed plan. Before the rivals, temperature_bias or bias_drift was adopted
// on 32 of 50 seeds (seeds 2 and 3 among them: bias_drift, temperature_bias); now the candidate is not named, the rival is named
// beside it, and what to capture to tell them apart is said.
TEST(RivalExplanations, ABiasThatShiftsWhileTurningIsNotNamedAWarmUp) {
  physgen::Effects e;
  e.turntable_bias = {0.8, -0.5, -1.0};
  for (unsigned long long seed : {1ull, 2ull, 3ull}) {
    const DiagnosisReport r = DiagnosePhysics(e, seed);
    EXPECT_TRUE(r.adopted.empty()) << "seed " << seed << "\n" << FormatDiagnosis(r);
    EXPECT_TRUE(r.unexplained) << FormatDiagnosis(r);
    ASSERT_EQ(r.ambiguous.size(), 2u) << FormatDiagnosis(r);
    EXPECT_EQ(r.ambiguous[1], "turntable_bias_shift") << FormatDiagnosis(r);
    EXPECT_TRUE(testing::Contains(r.next_captures, "take a static pose again between the turntable runs"))
        << r.next_captures;
    EXPECT_EQ(r.final_fit.parameters, r.base.parameters);
  }
}

// Where the plan does separate them, the library's effect beats the rivals and is named: a
// warm-up inside the static poses is not a shift of the turntable runs.
TEST(RivalExplanations, AWarmUpIsStillNamedWhereThePlanSeparatesIt) {
  physgen::Effects e;
  e.temp_bias = {0.5, -0.3, 0.8};  // the physics bench's temperature_bias case
  const DiagnosisReport r = DiagnosePhysics(e, 3);
  ASSERT_EQ(r.adopted_names(), std::vector<std::string>{"temperature_bias"}) << FormatDiagnosis(r);
  bool weighed = false;
  for (const CandidateScore& c : r.rounds.front().candidates)
    weighed = weighed || testing::Contains(c.rejected_reason, "a rival outside the library");
  EXPECT_TRUE(weighed) << FormatDiagnosis(r);
}

TEST(RivalExplanations, EachKindIsOfferedWhereTheCapturesIdentifyIt) {
  const testing::PhysicsSet set = testing::MakePhysicsSet(physgen::Effects{}, 1);
  const std::vector<FitCapture> captures = FitCaptures(set);
  const std::vector<RivalExplanation> rivals = RivalExplanations(captures);
  int shifts = 0, asymmetries = 0;
  for (const RivalExplanation& r : rivals) {
    shifts += r.effect->Name() == "turntable_bias_shift";
    asymmetries += r.effect->Name() == "scale_asymmetry";
  }
  EXPECT_EQ(rivals.size(), 2u);
  EXPECT_EQ(shifts, 1);
  EXPECT_EQ(asymmetries, 1);
  // Static captures only: no shift while turning can be told.
  std::vector<FitCapture> still;
  for (const FitCapture& c : captures)
    if (c.kind == CaptureKind::kStatic) still.push_back(c);
  for (const RivalExplanation& r : RivalExplanations(still)) EXPECT_NE(r.effect->Name(), "turntable_bias_shift");
}

// The asymmetry's correction inverts raw = b + k u + d |u| on both sides of zero.
TEST(RivalExplanations, TheScaleAsymmetryInvertsItsResponse) {
  const testing::PhysicsSet set = testing::MakePhysicsSet(physgen::Effects{}, 1);
  const std::vector<FitCapture> captures = FitCaptures(set);
  const Effect* asym = nullptr;
  const std::vector<RivalExplanation> rivals = RivalExplanations(captures);
  for (const RivalExplanation& r : rivals)
    if (r.effect->Name() == "scale_asymmetry") asym = r.effect.get();
  ASSERT_NE(asym, nullptr);
  SensorModel base;
  base.bias_counts = {2048.0, 2040.0, 2060.0};
  base.scale_counts_per_mps2 = {34.8, 35.0, 34.4};
  const double d[3] = {0.1, -0.05, 0.2};
  for (double u : {-9.8, -3.0, 4.0, 19.6}) {
    CorrectedCapture out{};
    for (int j = 0; j < 3; ++j)
      out.raw_counts(j) = base.bias_counts(j) + base.scale_counts_per_mps2(j) * u + d[j] * std::fabs(u);
    asym->Correct(d, base, captures.front(), EffectContext{}, &out);
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(out.raw_counts(j), base.bias_counts(j) + base.scale_counts_per_mps2(j) * u, 1e-9) << u;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Physics, OutsideTheLibrary,
    ::testing::Values(Outside{"asymmetric_scale", [](physgen::Effects* e) { e->asym_scale = {0.003, 0, 0}; }},
                      Outside{"bias_jump", [](physgen::Effects* e) { e->bias_jump = {2.0, 0.0, -1.5}; }}),
    [](const auto& test_info) { return std::string(test_info.param.name); });

TEST(Guard, ImplausibleParametersAreNamed) {
  const std::vector<FitCapture> none;
  SensorModel base;
  base.scale_counts_per_mps2 = {34.8, 34.8, 34.8};
  const double negative_loss = -1e-3;
  EXPECT_TRUE(testing::Contains(FindEffect("turntable_tilt")->WhyImplausible(&negative_loss, base, none),
                                "no tilt can do"));
  const double tilt_10deg = 1.0 - std::cos(10.0 * M_PI / 180.0);
  EXPECT_TRUE(testing::Contains(FindEffect("turntable_tilt")->WhyImplausible(&tilt_10deg, base, none),
                                "tilted 10.0 deg"));
  const double ok_loss = 1.0 - std::cos(2.0 * M_PI / 180.0);
  EXPECT_EQ(FindEffect("turntable_tilt")->WhyImplausible(&ok_loss, base, none), "");
  const double dr = 0.05;
  EXPECT_TRUE(testing::Contains(FindEffect("radius_offset")->WhyImplausible(&dr, base, none), "50.0 mm"));
  const double tc[3] = {0.5, 5.0, 0.1};  // 5 counts/degC = 14 mg/degC on y
  EXPECT_TRUE(testing::Contains(FindEffect("temperature_bias")->WhyImplausible(tc, base, none), "axis y"));
}

TEST(Guard, StructureInTimeIsFoundAndNoiseIsNot) {
  std::vector<FitCapture> captures(18);
  std::vector<double> trend, noise;
  std::mt19937_64 rng(5);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 18; ++i) {
    captures[i].mean_t_s = 30.0 * i;
    captures[i].mean_counts = Eigen::Vector3d(2048 + 340 * ((i % 3) - 1), 2048 + 340 * (((i / 3) % 3) - 1), 2048 + 340 * (i % 2 ? 1 : -1));
    noise.push_back(unit(rng));
    trend.push_back(noise.back() + 0.4 * (i - 8.5));
  }
  const ResidualStructure found = FindResidualStructure(captures, trend);
  ASSERT_TRUE(found.Found(0.01)) << found.Describe();
  EXPECT_TRUE(testing::Contains(found.Describe(), "time")) << found.Describe();
  EXPECT_FALSE(FindResidualStructure(captures, noise).Found(0.01));
}

TEST(Guard, WorstOfNormalsPValue) {
  // One normal beyond 1.96 has p 0.05; the worst of 18 beyond 3 sigma about 0.047.
  EXPECT_NEAR(WorstOfNormalsPValue(1.959964, 1), 0.05, 1e-5);
  EXPECT_NEAR(WorstOfNormalsPValue(3.0, 18), 1.0 - std::pow(1.0 - 0.0026998, 18), 1e-5);
  EXPECT_EQ(WorstOfNormalsPValue(0.0, 5), 1.0);
}

}  // namespace
}  // namespace accelcal
