// The diagnosis loop on virtual-bench data with an undeclared effect in it (issue 5).
#include "accelcal/calibration/diagnosis/diagnosis.h"

#include <gtest/gtest.h>

#include "accelcal/calibration/capture_screening.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/virtual_bench.h"

namespace accelcal {
namespace {

// The default bench session, with a temperature that warms up over it (so temperature and time
// are not the same regressor) and the given effects injected.
sim::Scenario Bench(std::uint64_t seed) {
  sim::Scenario s = sim::DefaultScenario();
  s.bench.seed = seed;
  s.effects.temperature = sim::TemperatureRamp{21.0, 31.0, 200.0};
  return s;
}

std::vector<FitCapture> Captures(const sim::Scenario& scenario) {
  sim::VirtualBench bench(scenario);
  std::vector<Capture> captures = bench.SimulateCaptureSet();
  ScreeningOptions screening;
  screening.adc_range = scenario.adc.Range();
  ScreenCaptures(captures, screening);
  std::vector<FitCapture> out;
  for (const Capture& c : captures)
    if (c.used()) out.push_back(MakeFitCapture(c));
  return out;
}

DiagnosisReport DiagnoseBench(const sim::Scenario& scenario, bool loo = false) {
  DiagnosisOptions options;
  options.leave_one_out = loo;
  return Diagnose(Captures(scenario), FitOptions{}, options);
}

struct Injection {
  const char* effect;
  void (*inject)(sim::EffectsSpec*);
};

// Realistic sizes: a few mg of nonlinearity at 2.4 g, 0.5 mg/degC, 1e-4/degC, a count per
// five minutes, 3 mm of radius, 0.5 % of speed, proof masses a few mm apart.
const Injection kInjections[] = {
    {"quadratic_nonlinearity", [](sim::EffectsSpec* e) { e->quadratic_counts_per_mps2_sq = {0.004, -0.003, 0.002}; }},
    {"temperature_bias", [](sim::EffectsSpec* e) { e->bias_temp_coeff_counts_per_c = {0.2, -0.15, 0.25}; }},
    {"temperature_scale", [](sim::EffectsSpec* e) { e->scale_temp_coeff_per_c = {1.5e-4, -1e-4, 2e-4}; }},
    {"bias_drift", [](sim::EffectsSpec* e) { e->bias_drift_counts_per_s = {0.003, -0.002, 0.0025}; }},
    {"radius_offset", [](sim::EffectsSpec* e) { e->radius_offset_m = 0.003; }},
    {"rpm_scale", [](sim::EffectsSpec* e) { e->rpm_scale = 0.005; }},
    {"size_effect", [](sim::EffectsSpec* e) { e->size_effect_m = {0.004, -0.003, 0.005}; }},
};

class EachEffect : public ::testing::TestWithParam<Injection> {};

TEST_P(EachEffect, IsNamedFirstAndBringsTheRmsDownToTheNoise) {
  for (std::uint64_t seed : {3u, 4u}) {
    sim::Scenario scenario = Bench(seed);
    GetParam().inject(&scenario.effects);
    const DiagnosisReport r = DiagnoseBench(scenario, /*loo=*/true);
    ASSERT_TRUE(r.base.IsUsable()) << r.base.message;
    ASSERT_FALSE(r.adopted.empty()) << FormatDiagnosis(r);
    EXPECT_EQ(r.adopted.front().name, GetParam().effect) << FormatDiagnosis(r);
    EXPECT_LE(r.final_fit.residual_rms_mps2, 1.5 * r.noise_rms_mps2) << FormatDiagnosis(r);
    EXPECT_GT(r.base.residual_rms_mps2, 1.5 * r.noise_rms_mps2) << "the injection was too small";
    EXPECT_FALSE(r.adopted.front().evidence.empty());
  }
}

INSTANTIATE_TEST_SUITE_P(Library, EachEffect, ::testing::ValuesIn(kInjections),
                         [](const auto& test_info) { return std::string(test_info.param.effect); });

TEST(Diagnosis, CleanDataGetsNoEffectInAtLeast95Of100Seeds) {
  int false_alarms = 0;
  for (std::uint64_t seed = 1000; seed < 1100; ++seed) {
    const DiagnosisReport r = DiagnoseBench(Bench(seed));
    ASSERT_TRUE(r.base.IsUsable());
    false_alarms += !r.adopted.empty();
  }
  EXPECT_LE(false_alarms, 5);
}

TEST(Diagnosis, TwoEffectsTogetherAreBothFound) {
  sim::Scenario scenario = Bench(7);
  scenario.effects.quadratic_counts_per_mps2_sq = {0.004, -0.003, 0.002};
  scenario.effects.radius_offset_m = 0.003;
  const DiagnosisReport r = DiagnoseBench(scenario);
  const std::vector<std::string> names = r.adopted_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "quadratic_nonlinearity"), names.end()) << FormatDiagnosis(r);
  EXPECT_NE(std::find(names.begin(), names.end(), "radius_offset"), names.end()) << FormatDiagnosis(r);
  EXPECT_LE(r.final_fit.residual_rms_mps2, 1.5 * r.noise_rms_mps2) << FormatDiagnosis(r);
}

TEST(Diagnosis, RecoversTheInjectedParameter) {
  sim::Scenario scenario = Bench(8);
  scenario.effects.radius_offset_m = 0.003;
  const DiagnosisReport r = DiagnoseBench(scenario);
  ASSERT_EQ(r.adopted.size(), 1u) << FormatDiagnosis(r);
  EXPECT_NEAR(r.adopted[0].parameters[0], 0.003, 4 * r.adopted[0].uncertainty[0] + 1e-5);
}

TEST(Diagnosis, SkipsWhatTheDataCannotIdentifyWithTheReason) {
  sim::Scenario scenario = Bench(9);
  scenario.effects.temperature.reset();           // constant temperature
  scenario.captures.resize(9);                    // static poses only, each taken twice
  for (int i = 0; i < 9; ++i) scenario.captures.push_back(scenario.captures[i]);
  scenario.effects.bias_drift_counts_per_s = {0.01, -0.01, 0.01};
  const DiagnosisReport r = DiagnoseBench(scenario);
  ASSERT_FALSE(r.rounds.empty());
  bool radius_skipped = false, temperature_skipped = false;
  for (const CandidateScore& c : r.rounds.front().candidates) {
    if (c.effect == "radius_offset") radius_skipped = c.skipped_reason.find("turntable") != std::string::npos;
    if (c.effect == "temperature_bias") temperature_skipped = c.skipped_reason.find("temperature") != std::string::npos;
  }
  EXPECT_TRUE(radius_skipped) << FormatDiagnosis(r);
  EXPECT_TRUE(temperature_skipped) << FormatDiagnosis(r);
}

}  // namespace
}  // namespace accelcal
