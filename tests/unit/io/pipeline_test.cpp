// End to end through the library: the virtual bench makes a session with a known truth, it is
// written in the capture-set format and read back, screened and fitted; the fit must recover the
// truth. Likewise for a continuous hand-held recording through the static-interval detector.
#include <sstream>

#include <fmt/core.h>

#include <gtest/gtest.h>

#include "accelcal/calibration/apply.h"
#include "accelcal/calibration/capture_screening.h"
#include "accelcal/calibration/fit/calibration_fit.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/io/capture_set_reader.h"
#include "accelcal/io/capture_set_writer.h"
#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/recording_reader.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/virtual_bench.h"
#include "accelcal/acquire/static_detector.h"
#include "accelcal/io/scenario_file.h"

namespace accelcal {
namespace {

// Truth within 4.5 sigma of the reported uncertainty, and that uncertainty small in absolute
// terms (a 12-bit part at ~35 counts per m/s^2, noise ~1.5 counts).
void ExpectRecovered(const FitSummary& s, const SensorModel& truth, const std::string& context) {
  ASSERT_TRUE(s.IsUsable()) << context << "\n" << s.FullReport();
  const auto t = truth.ToVector();
  for (int i = 0; i < kNumBaseParameters; ++i)
    EXPECT_LT(std::fabs(s.parameters(i) - t(i)), 4.5 * s.uncertainty(i))
        << ParameterName(i) << " " << context << "\n" << s.FullReport();
  EXPECT_LT(s.uncertainty.segment<3>(kBiasX).maxCoeff(), 0.2);
  EXPECT_LT((s.uncertainty.segment<3>(kScaleX).array() / t.segment<3>(kScaleX).array()).maxCoeff(), 5e-4);
  EXPECT_LT(s.uncertainty.segment<3>(kMisYZ).maxCoeff(), 1e-3);
}

CaptureSet RoundTrip(const CaptureSet& set) {
  std::ostringstream csv;
  WriteCaptureSet(csv, set);
  return ParseCaptureSet(csv.str(), "roundtrip.csv");
}

TEST(Pipeline, SimulatedCaptureSetRecoversTruthOverSeeds) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    sim::Scenario scenario = sim::DefaultScenario();
    scenario.bench.seed = seed;
    sim::VirtualBench bench(scenario);
    CaptureSet set;
    set.captures = bench.SimulateCaptureSet();
    set.adc_range = scenario.adc.Range();
    CaptureSet read = RoundTrip(set);
    ASSERT_EQ(read.captures.size(), 18u);
    ScreeningOptions screening;
    screening.adc_range = read.adc_range;
    ScreenCaptures(read.captures, screening);
    FitOptions options;
    options.gravity = GravitySpec::Given(scenario.bench.gravity_mps2);
    const FitSummary s = FitCalibration(read.captures, options);
    ExpectRecovered(s, scenario.sensor.model, "seed " + std::to_string(seed));
    // Clean data: the residuals are what the noise explains.
    EXPECT_LT(s.Chi2PerDof(), 3.0) << "seed " << seed;
  }
}

TEST(Pipeline, ClippedCaptureIsLeftOutAndTheFitGoesOn) {
  sim::Scenario scenario = sim::DefaultScenario();
  // The last z-radial run at 200 rpm reaches 0.15 m * (2 pi 200/60)^2 = 66 m/s^2 > 6 g: it clips.
  scenario.captures.back().rpm = 200.0;
  sim::VirtualBench bench(scenario);
  CaptureSet set;
  set.captures = bench.SimulateCaptureSet();
  set.adc_range = scenario.adc.Range();
  CaptureSet read = RoundTrip(set);
  ScreeningOptions screening;
  screening.adc_range = read.adc_range;
  ScreenCaptures(read.captures, screening);
  EXPECT_FALSE(read.captures.back().used());
  EXPECT_NE(read.captures.back().rejection_reason.find("clipped"), std::string::npos)
      << read.captures.back().rejection_reason;
  const FitSummary s = FitCalibration(read.captures, FitOptions{});
  ExpectRecovered(s, scenario.sensor.model, "one capture clipped");
  EXPECT_EQ(s.num_captures, 17);
  const Calibration cal = MakeCalibration(s, GravitySpec::Standard(), read.captures, "x.csv");
  EXPECT_FALSE(cal.captures.back().used);
  EXPECT_TRUE(std::isnan(cal.captures.back().residual_mps2));
}

TEST(Pipeline, SimulatedHandRecordingRecoversTruth) {
  const sim::Scenario scenario =
      sim::LoadScenario(std::string(ACCELCAL_SOURCE_DIR) + "/scenarios/hand_recording.toml");
  sim::VirtualBench bench(scenario);
  std::ostringstream text;
  WriteRecording(text, bench.SimulateRecording());
  const std::vector<Sample> samples = ParseRecording(text.str(), "rec.txt");
  const StaticDetection detection = DetectStaticIntervals(samples, StaticDetectorOptions{});
  EXPECT_EQ(detection.intervals.size(), scenario.captures.size());
  std::vector<Capture> captures = CapturesFromIntervals(samples, detection);
  ScreenCaptures(captures, ScreeningOptions{});
  const FitSummary s = FitCalibration(captures, FitOptions{});
  ExpectRecovered(s, scenario.sensor.model, "hand recording");
}

TEST(Pipeline, CalibrationFileRoundTripsAndApplies) {
  sim::VirtualBench bench(sim::DefaultScenario());
  std::vector<Capture> captures = bench.SimulateCaptureSet();
  captures[3].rejection_reason = "left out for the test, with \"quotes\"";
  const FitSummary s = FitCalibration(captures, FitOptions{});
  ASSERT_TRUE(s.IsUsable());
  const Calibration cal = MakeCalibration(s, GravitySpec::FromLocation(-34.9, 43.0), captures, "c.csv");
  const Calibration back = CalibrationFromJson(CalibrationToJson(cal), "mem");
  EXPECT_EQ(back.model.ToVector(), cal.model.ToVector());  // exact: full precision
  EXPECT_EQ(back.uncertainty.ToVector(), cal.uncertainty.ToVector());
  EXPECT_EQ(back.gravity.gravity_mps2, cal.gravity.gravity_mps2);
  EXPECT_EQ(back.gravity.source, GravitySpec::Source::kWgs84);
  ASSERT_EQ(back.captures.size(), captures.size());
  EXPECT_FALSE(back.captures[3].used);
  EXPECT_EQ(back.captures[3].reason, captures[3].rejection_reason);
  EXPECT_EQ(back.captures[5].residual_mps2, cal.captures[5].residual_mps2);

  // apply: the mean of a capture comes out with magnitude g (within its residual).
  const Eigen::Vector3d mean = ComputeStats(captures[0].samples).mean_counts;
  std::istringstream in(fmt::format("# header\n1.5 {} {} {}\n", mean.x(), mean.y(), mean.z()));
  std::ostringstream out;
  int errors = 0;
  const ApplyStreamResult r = ApplyStream(in, out, CalibrationApplier(back), "in", [&](const InputError&) { ++errors; });
  EXPECT_EQ(r.samples, 1);
  EXPECT_EQ(errors, 0);
  double t, ax, ay, az;
  std::istringstream parsed(out.str().substr(out.str().find('\n') + 1));
  parsed >> t >> ax >> ay >> az;
  EXPECT_EQ(t, 1.5);
  EXPECT_NEAR(std::sqrt(ax * ax + ay * ay + az * az), 9.80665, 0.005);
}

TEST(Pipeline, ApplyReportsMalformedLinesAndGoesOn) {
  Calibration cal;
  cal.model.bias_counts = {2048, 2048, 2048};
  cal.model.scale_counts_per_mps2 = {40, 40, 40};
  std::istringstream in("0 2048 2048 2448\n0.1 2048 x 2448\n0.2 2048 2048 nan\n0.3,2088,2048,2048\n");
  std::ostringstream out;
  std::vector<std::string> errors;
  const ApplyStreamResult r = ApplyStream(in, out, CalibrationApplier(cal), "in", [&](const InputError& e) { errors.push_back(e.what()); });
  EXPECT_EQ(r.samples, 2);
  EXPECT_EQ(r.malformed, 2);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NE(errors[0].find("in:2:10: field 'ay': 'x' is not a number"), std::string::npos) << errors[0];
  EXPECT_NE(errors[1].find("in:3:"), std::string::npos) << errors[1];
  EXPECT_EQ(out.str(), "0 0.000000 0.000000 10.000000\n0.3 1.000000 0.000000 0.000000\n");
}


// An adopted effect as the calibration holds it: its parameters (units and sigmas not needed).
CalibrationEffect EffectWith(std::string name, std::vector<std::pair<std::string, double>> parameters,
                         bool corrects_readings = true) {
  CalibrationEffect e;
  e.name = std::move(name);
  for (const auto& [key, value] : parameters) e.parameters.push_back({key, "", value, kNaN});
  e.corrects_readings = corrects_readings;
  return e;
}

TEST(Pipeline, ApplyRefusesEffectsItCannotApply) {
  Calibration cal;
  cal.effects = {EffectWith("flux_capacitor", {})};
  EXPECT_THROW(CalibrationApplier{cal}, Error);
  cal.effects = {EffectWith("quadratic_nonlinearity", {{"q_x", 0.1}})};
  EXPECT_THROW(CalibrationApplier{cal}, Error);  // q_y, q_z missing
}

}  // namespace
}  // namespace accelcal

namespace accelcal {
namespace {

// A calibration with a quadratic and a temperature-bias effect must invert the forward model:
// raw = b + tc (T - Tref) + k u + q u^2 (no misalignment here) gives back u.
TEST(Pipeline, ApplierInvertsSensorEffects) {
  Calibration cal;
  cal.model.bias_counts = {2048, 2040, 2060};
  cal.model.scale_counts_per_mps2 = {35, 34, 36};
  cal.reference = {25.0, 100.0};
  cal.effects = {EffectWith("quadratic_nonlinearity", {{"q_x", 0.01}, {"q_y", -0.02}, {"q_z", 0.005}}),
                 EffectWith("temperature_bias", {{"tc_bias_x", 0.5}, {"tc_bias_y", -0.25}, {"tc_bias_z", 0.1}}),
                 EffectWith("radius_offset", {{"dr", 0.003}}, false)};
  const CalibrationApplier applier(cal);
  EXPECT_TRUE(applier.needs_temperature());
  ASSERT_EQ(applier.not_applied().size(), 1u);
  EXPECT_NE(applier.not_applied()[0].find("radius_offset"), std::string::npos);

  const Eigen::Vector3d u(3.0, -9.0, 20.0);
  const Eigen::Vector3d q(0.01, -0.02, 0.005), tc(0.5, -0.25, 0.1);
  Sample s;
  s.temp_c = 31.0;
  for (int j = 0; j < 3; ++j)
    s.raw_counts(j) = cal.model.bias_counts(j) + tc(j) * (s.temp_c - 25.0) +
                      cal.model.scale_counts_per_mps2(j) * u(j) + q(j) * u(j) * u(j);
  EXPECT_LT((applier.Apply(s) - u).norm(), 1e-9);
  s.temp_c = kNaN;
  EXPECT_THROW(applier.Apply(s), Error);
}

TEST(Pipeline, ApplyStreamNamesLinesWithoutTheNeededTemperature) {
  Calibration cal;
  cal.model.scale_counts_per_mps2 = {35, 34, 36};
  cal.reference = {25.0, 0.0};
  cal.effects = {EffectWith("temperature_scale", {{"tc_scale_x", 1e-4}, {"tc_scale_y", 1e-4}, {"tc_scale_z", 1e-4}})};
  std::istringstream in("0 1 2 3\n");
  std::ostringstream out;
  std::vector<std::string> errors;
  ApplyStream(in, out, CalibrationApplier(cal), "in", [&](const InputError& e) { errors.push_back(e.what()); });
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("in:1: this calibration corrects for temperature"), std::string::npos) << errors[0];
}

}  // namespace
}  // namespace accelcal
