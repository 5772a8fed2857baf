// The calibration report: model (gathering, limits, analyses), the text / HTML / JSON renderers
// and the SVG plotter. Fixtures in tests/data/report/.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "accelcal/app/calibration_pipeline.h"
#include "accelcal/calibration/fit/calibration_fit.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/app/report_files.h"
#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/report/report_html.h"
#include "accelcal/io/report_json.h"
#include "accelcal/report/report_model.h"
#include "accelcal/report/report_text.h"
#include "accelcal/report/svg_plot.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/virtual_bench.h"
#include "accelcal/session/procedure.h"
#include "test_support.h"

namespace accelcal::report_test {
namespace {

using nlohmann::json;
using testing::Contains;
using testing::ExpectInputError;

const std::string kDataDir = std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/report/";

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

json ReadJson(const std::string& name) { return json::parse(ReadText(kDataDir + name)); }

// The first format's limits (1-sigma 2 counts, 2000 ppm, 0.005 rad) read by the stated rule:
// limits on U = 2 x 1-sigma (issue 27).
ProcedureLimits FixtureLimits() {
  ProcedureLimits l;
  l.min_captures = 15;
  l.max_residual_rms_mps2 = 0.05;
  l.max_residual_rms_noise = 5;
  l.max_bias_U_counts = 4;
  l.max_scale_U_ppm = 4000;
  l.max_misalignment_U_rad = 0.01;
  return l;
}

// The fixture file has no uncertainty budget (a calibration of `accelcal fit`): the limits on U
// need one. This one holds the fit's covariance alone (type A, k = 2): U = 2 sigma, so the
// fixture's figures are independent of any propagation.
UncertaintyBudget TypeAOnlyBudget(const Calibration& cal) {
  UncertaintyBudget b;
  const auto value = cal.model.ToVector();
  const auto sigma = cal.uncertainty.ToVector();
  for (int i = 0; i < kNumBaseParameters; ++i) {
    if (cal.FindHeld(i) != nullptr) continue;
    ParameterBudget p;
    p.index = i;
    p.name = std::string(ParameterName(i));
    p.unit = std::string(ParameterUnit(i));
    p.value = value(i);
    p.contributions.push_back({"fit (type A)", 'A', sigma(i), p.unit, 1.0, sigma(i),
                               std::numeric_limits<double>::infinity(), ""});
    p.combined = sigma(i);
    p.effective_dof = std::numeric_limits<double>::infinity();
    p.coverage_factor = 2.0;
    p.expanded = 2.0 * sigma(i);
    b.parameters.push_back(p);
  }
  return b;
}

// The fixture calibration with everything a report can show, except session captures.
ReportInputs FixtureInputs() {
  ReportInputs in;
  in.calibration = ReadCalibrationFile(kDataDir + "calibration.json");
  in.calibration.budget = TypeAOnlyBudget(in.calibration);
  in.meta.device = "MMA7260Q SN 0042";
  in.meta.operator_name = "J. Smith";
  in.meta.date_utc = "2025-03-01T14:05:09.123Z";
  in.meta.place = "Lab 2, bench 3";
  in.meta.session_name = "20250301T140509Z";
  in.meta.session_path = "/data/sessions/20250301T140509Z.db";
  in.meta.procedure = "Full calibration";
  in.meta.source = "sim";
  in.limits = FixtureLimits();
  in.allan = ParseAllanJson(ReadJson("allan.json"), "allan.json");
  in.noise = ParseNoiseJson(ReadJson("noise.json"), "noise.json");
  return in;
}

ReportModel FixtureModel() {
  ReportModel m = BuildReportModel(FixtureInputs());
  m.tool = "accelcal TEST";  // the golden file must not change with the version
  return m;
}

// ---- analyses (allan.json, noise.json) ---------------------------------------------------

TEST(ReportAnalyses, AllanFixtureIsReadFieldByField) {
  const json j = ReadJson("allan.json");
  const AllanSection a = ParseAllanJson(j, "allan.json");
  EXPECT_EQ(a.unit, "m/s^2");
  EXPECT_EQ(a.rate_hz, 100.0);
  for (int i = 0; i < 3; ++i) {
    const char* axis = i == 0 ? "x" : i == 1 ? "y" : "z";
    ASSERT_TRUE(a.axes[i].has_value()) << axis;
    EXPECT_EQ(a.axes[i]->noise_density, j["axes"][axis]["noise_density"].get<double>());
    EXPECT_EQ(a.axes[i]->bias_instability, j["axes"][axis]["bias_instability"].get<double>());
    EXPECT_EQ(a.axes[i]->tau_s, j["axes"][axis]["tau_s"].get<std::vector<double>>());
    EXPECT_EQ(a.axes[i]->adev_hi, j["axes"][axis]["adev_hi"].get<std::vector<double>>());
  }
}

TEST(ReportAnalyses, AllanErrorsNameTheField) {
  json j = ReadJson("allan.json");
  j["unit"] = "g";
  EXPECT_TRUE(Contains(ExpectInputError([&] { ParseAllanJson(j, "a.json"); }, "unit g").what(), "unit"));
  j = ReadJson("allan.json");
  j["axes"]["y"]["adev"].erase(0);
  EXPECT_TRUE(Contains(ExpectInputError([&] { ParseAllanJson(j, "a.json"); }, "lengths").what(), "axes.y.adev"));
  j = ReadJson("allan.json");
  j["axes"]["z"]["tau_s"][0] = 0.0;
  EXPECT_TRUE(Contains(ExpectInputError([&] { ParseAllanJson(j, "a.json"); }, "tau 0").what(), "positive"));
  j = ReadJson("allan.json");
  j["axes"]["x"]["noise_density"] = "big";
  EXPECT_TRUE(Contains(ExpectInputError([&] { ParseAllanJson(j, "a.json"); }, "string").what(),
                       "axes.x.noise_density"));
  j = ReadJson("allan.json");
  j["axes"] = json::object();
  ExpectInputError([&] { ParseAllanJson(j, "a.json"); }, "no axes");
  j = ReadJson("allan.json");
  j["axes"]["w"] = j["axes"]["x"];
  EXPECT_TRUE(Contains(ExpectInputError([&] { ParseAllanJson(j, "a.json"); }, "axis w").what(), "axes.w"));
}

TEST(ReportAnalyses, NoiseFixtureAndErrors) {
  const NoiseSection n = ParseNoiseJson(ReadJson("noise.json"), "noise.json");
  EXPECT_EQ(n.unit, "counts");
  ASSERT_TRUE(n.axes[2].has_value());
  EXPECT_EQ(n.axes[2]->std, 1.52);
  EXPECT_EQ(n.axes[0]->bias_repeatability, 0.35);
  json j = ReadJson("noise.json");
  j.erase("unit");
  EXPECT_TRUE(Contains(ExpectInputError([&] { ParseNoiseJson(j, "n.json"); }, "no unit").what(), "n.json"));
}

TEST(ReportAnalyses, NullsAndTheNoiseCommandsFileShape) {
  json j = ReadJson("allan.json");
  j["axes"]["x"]["adev"][0] = nullptr;
  j["axes"]["x"]["adev_lo"][0] = nullptr;
  j["axes"]["x"]["bias_instability"] = nullptr;
  const AllanSection a = ParseAllanJson(j, "a.json");
  EXPECT_TRUE(std::isnan(a.axes[0]->adev[0]));
  EXPECT_TRUE(std::isnan(a.axes[0]->bias_instability));
  EXPECT_EQ(a.axes[0]->adev[1], j["axes"]["x"]["adev"][1].get<double>());
  j["axes"]["x"]["tau_s"][0] = nullptr;  // tau is never null
  ExpectInputError([&] { ParseAllanJson(j, "a.json"); }, "null tau");

  const json noise = {{"format", "accelcal-noise/1"},
                      {"unit", "m/s^2"},
                      {"records", json::array({{{"axes", {{"x", {{"std", 0.01}, {"density", 0.002}}},
                                                          {"z", {{"std", 0.03}, {"density", nullptr}}}}}},
                                               {{"axes", json::object()}}})},
                      {"repeatability", {{"std_of_means", {0.001, nullptr, 0.003}}}}};
  const NoiseSection n = ParseNoiseJson(noise, "n.json");
  EXPECT_EQ(n.unit, "m/s^2");
  EXPECT_EQ(n.source, "n.json, record 1 of 2");
  ASSERT_TRUE(n.axes[0] && n.axes[2]);
  EXPECT_FALSE(n.axes[1].has_value());
  EXPECT_EQ(n.axes[0]->std, 0.01);
  EXPECT_EQ(n.axes[0]->noise_density, 0.002);
  EXPECT_EQ(n.axes[0]->bias_repeatability, 0.001);
  EXPECT_TRUE(std::isnan(n.axes[2]->noise_density));
  EXPECT_EQ(n.axes[2]->bias_repeatability, 0.003);
}

TEST(ReportAnalyses, ReadFromASessionResult) {
  json result = CalibrationToJson(ReadCalibrationFile(kDataDir + "calibration.json"));
  result["allan"] = ReadJson("allan.json");
  result["noise"] = ReadJson("noise.json");
  ReportInputs in;
  ReadAnalysesFromResult(result, "s.db", &in);
  ASSERT_TRUE(in.allan && in.noise);
  EXPECT_EQ(in.allan->axes[1]->tau_s.size(), 14u);
  result["noise"]["unit"] = "furlongs";
  ExpectInputError([&] { ReadAnalysesFromResult(result, "s.db", &in); }, "bad noise in result");
}

// ---- model -------------------------------------------------------------------------------

TEST(ReportModel, FromACalibrationFileAlone) {
  const json j = ReadJson("calibration.json");
  ReportInputs in;
  in.calibration = CalibrationFromJson(j, "calibration.json");
  const ReportModel m = BuildReportModel(in);
  EXPECT_TRUE(m.meta.device.empty());
  EXPECT_EQ(m.verdict, Verdict::kNoLimits);
  ASSERT_EQ(m.parameters.size(), 9u);
  EXPECT_EQ(m.parameters[0].value, j["bias_counts"][0].get<double>());
  EXPECT_EQ(m.parameters[5].sigma, j["uncertainty"]["scale_counts_per_mps2"][2].get<double>());
  EXPECT_EQ(m.captures.size(), j["captures"].size());
  EXPECT_EQ(m.captures_left_out, 1);
  // Only the adopted model's residuals are known from a file.
  ASSERT_EQ(m.stages.size(), 1u);
  EXPECT_EQ(m.stages[0].residual_mps2[3], j["captures"][3]["residual_mps2"].get<double>());
  ASSERT_EQ(m.effects.size(), 1u);
  EXPECT_EQ(m.effects[0].rms_before_mps2, 0.0123);
  ASSERT_EQ(m.effects[0].parameters.size(), 3u);
  EXPECT_EQ(m.effects[0].parameters[2].name, "tb_z");
  EXPECT_EQ(m.effects[0].parameters[2].sigma, 0.0019);
  EXPECT_TRUE(std::isnan(m.temp_min_c));
  // Noise RMS: the RMS of the used captures' sigma, from the file.
  double sum = 0;
  int n = 0;
  for (const json& c : j["captures"])
    if (c["used"].get<bool>()) { sum += std::pow(c["sigma_mps2"].get<double>(), 2); ++n; }
  EXPECT_NEAR(m.noise_rms_mps2, std::sqrt(sum / n), 1e-15);
}

// Issue 14: a reduced model (six faces: the angles held at 0) is marked in every report form,
// not only listed among the warnings.
TEST(ReportModel, HeldParametersAreMarkedInTheTableTextHtmlAndJson) {
  SensorModel truth;
  truth.bias_counts = {2051.3, 2037.8, 2069.2};
  truth.scale_counts_per_mps2 = {34.91, 35.42, 34.17};
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 1.5);
  CalibrationRequest request;
  for (const Eigen::Vector3d& up : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(1, 0, 0),
                                    Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, -1, 0)}) {
    Capture c;
    c.id = static_cast<int>(request.captures.size()) + 1;
    c.kind = CaptureKind::kStatic;
    const Eigen::Vector3d raw = truth.Raw(9.80665 * up);
    for (int i = 0; i < 500; ++i) {
      Sample s;
      s.t_s = c.id * 100.0 + i * 0.01;
      s.raw_counts = raw + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
      c.samples.push_back(s);
    }
    request.captures.push_back(c);
  }
  request.source_name = "six faces";
  const CalibrationOutcome outcome = CalibrateCaptures(request);
  ASSERT_TRUE(outcome.usable()) << outcome.diagnosis.base.message;
  ReportInputs in;
  in.calibration = outcome.MakeCalibration(true);
  ASSERT_EQ(in.calibration.held.size(), 3u);
  const ReportModel m = BuildReportModel(in);
  ASSERT_EQ(m.parameters.size(), 9u);
  for (size_t i = 0; i < 9; ++i) EXPECT_EQ(m.parameters[i].held, i >= 6) << m.parameters[i].name;
  const std::string report_text = RenderReportText(m);
  // The parameter table (the warnings above it name the held parameters too).
  const std::string text = report_text.substr(report_text.find("  Parameter "));
  const std::string held_row = text.substr(text.find(m.parameters[6].name));
  EXPECT_EQ(held_row.substr(0, held_row.find('\n')).find("held") != std::string::npos, true) << held_row;
  const std::string fitted_row = text.substr(text.find(m.parameters[0].name));
  EXPECT_EQ(fitted_row.substr(0, fitted_row.find('\n')).find("held"), std::string::npos);
  EXPECT_TRUE(Contains(RenderReportHtml(m), "<td class=\"n\">held</td>"));
  const json j = json::parse(ReportJsonText(m));
  EXPECT_TRUE(j["parameters"][6]["held"].get<bool>());
  EXPECT_FALSE(j["parameters"][0]["held"].get<bool>());
}

TEST(ReportModel, EffectFieldsOfTheWrongTypeAreRefusedNamingTheField) {
  // Read strictly (io/calibration_file.h): a damaged effect never reaches a report as a
  // made-up or silently absent value; the file and the field are named.
  json j = ReadJson("calibration.json");
  j["effects"] = json::array({{{"name", 3}, {"parameters", json::object()}}});
  EXPECT_TRUE(Contains(ExpectInputError([&] { CalibrationFromJson(j, "c.json"); }, "name 3").what(),
                       "effects[0].name"));
  j["effects"] = json::array({{{"name", "bias_drift"}, {"rms_before_mps2", "x"}, {"parameters", json::object()}}});
  EXPECT_TRUE(Contains(ExpectInputError([&] { CalibrationFromJson(j, "c.json"); }, "rms x").what(),
                       "effects[0].rms_before_mps2"));
  j["effects"] = json::array({{{"name", "bias_drift"}, {"corrects_readings", "yes"}, {"parameters", json::object()}}});
  EXPECT_TRUE(Contains(ExpectInputError([&] { CalibrationFromJson(j, "c.json"); }, "yes").what(),
                       "effects[0].corrects_readings"));
  j["effects"] = json::array({{{"name", "bias_drift"}, {"parameters", 5}}});
  EXPECT_TRUE(Contains(ExpectInputError([&] { CalibrationFromJson(j, "c.json"); }, "parameters 5").what(),
                       "effects[0].parameters"));
}

TEST(ReportModel, LimitsAreCheckedAgainstIndependentFigures) {
  ReportInputs in = FixtureInputs();
  const json j = ReadJson("calibration.json");
  ReportModel m = BuildReportModel(in);
  ASSERT_EQ(m.checks.size(), 6u);
  EXPECT_EQ(m.verdict, Verdict::kPass);
  // The limits on U judge the U the certificate prints: here 2 x the 1-sigma (the fixture's
  // budget is type A alone). Largest relative scale U: 2 x 0.0135 / 35.012345 -> 771.2 ppm.
  EXPECT_NEAR(m.checks[4].value, 2 * 0.0135 / 35.012345 * 1e6, 1e-9);
  EXPECT_NEAR(m.checks[3].value, 2 * 0.52, 1e-15);
  EXPECT_NEAR(m.checks[5].value, 2 * 0.00033, 1e-15);
  EXPECT_TRUE(m.checks[4].on_uncertainty);
  EXPECT_EQ(m.checks[0].value, 18.0);  // captures_used from the file's fit
  EXPECT_EQ(m.checks[1].value, j["residual_rms_mps2"].get<double>());
  // A limit just below the measured value fails, and fails the whole.
  in.limits->max_scale_U_ppm = 771.0;
  m = BuildReportModel(in);
  EXPECT_FALSE(m.checks[4].pass);
  EXPECT_TRUE(m.checks[3].pass);
  EXPECT_EQ(m.verdict, Verdict::kFail);
  in.limits->max_scale_U_ppm = kNaN;
  in.limits->min_captures = 19;  // 18 used
  m = BuildReportModel(in);
  EXPECT_EQ(m.checks.size(), 5u);
  EXPECT_FALSE(m.checks[0].pass);
  EXPECT_EQ(m.verdict, Verdict::kFail);
}

// Issue 12, problem 4: a skipped step vanished and the report said PASS.
TEST(ReportModel, ASkippedRequiredStepOrAMissingOperatorMakesItIncomplete) {
  ReportInputs in = FixtureInputs();
  ASSERT_EQ(BuildReportModel(in).verdict, Verdict::kPass);
  SessionGaps gaps;
  gaps.steps.push_back({"diagnosis", "Diagnosis", "skipped", false});
  in.gaps = gaps;
  ReportModel m = BuildReportModel(in);
  EXPECT_EQ(m.verdict, Verdict::kPass);  // not required: listed, not held against it
  const std::string listed = RenderReportText(m);
  EXPECT_TRUE(Contains(listed, "7. Steps skipped or missing")) << listed;
  EXPECT_TRUE(Contains(listed, "Diagnosis (diagnosis): skipped")) << listed;
  in.gaps->steps.push_back({"pose_mx", "-x up", "skipped", true});
  m = BuildReportModel(in);
  EXPECT_EQ(m.verdict, Verdict::kIncomplete);
  ASSERT_EQ(m.incomplete.size(), 1u);
  EXPECT_EQ(m.incomplete[0], "required step '-x up' skipped");
  const std::string text = RenderReportText(m);
  EXPECT_TRUE(Contains(text, "Result:             INCOMPLETE")) << text;
  EXPECT_TRUE(Contains(text, "-x up (pose_mx, required): skipped")) << text;
  EXPECT_TRUE(Contains(RenderReportHtml(m), "INCOMPLETE:</b> required step &#39;-x up&#39; skipped") ||
              Contains(RenderReportHtml(m), "INCOMPLETE:</b> required step '-x up' skipped"));
  EXPECT_EQ(json::parse(ReportJsonText(m)).at("verdict"), "INCOMPLETE");
  // Issue 27, item 8: a mounting's three runs skipped were three alike lines; now one.
  in.gaps->steps.push_back({"tt_x_050", "+x radial, +z up at 50 mm, 120 rpm", "skipped", true});
  in.gaps->steps.push_back({"tt_x_100", "+x radial, +z up at 100 mm, 120 rpm", "skipped", true});
  m = BuildReportModel(in);
  ASSERT_EQ(m.incomplete.size(), 1u);
  EXPECT_EQ(m.incomplete[0], "required steps skipped: '-x up', '+x radial, +z up at 50 mm, 120 rpm', "
                             "'+x radial, +z up at 100 mm, 120 rpm'");
  in.gaps->steps.clear();
  in.gaps->identification = {"operator"};
  EXPECT_EQ(BuildReportModel(in).verdict, Verdict::kIncomplete);
  // A limit that fails is FAIL, whatever else is missing.
  in.limits->min_captures = 19;
  EXPECT_EQ(BuildReportModel(in).verdict, Verdict::kFail);
}

// Issue 12, problem 1: a speed scale adopted on the standard gravity cannot be told from a
// gravity error: the report cannot say PASS.
TEST(ReportModel, ASpeedScaleOnTheStandardGravityIsIncomplete) {
  ReportInputs in = FixtureInputs();
  CalibrationEffect rpm;
  rpm.name = "rpm_scale";
  rpm.parameters.push_back({"rpm_scale", "", -0.0013, 0.0001});
  in.calibration.effects = {rpm};
  // WGS84 gravity: still not PASS, the turntable not being verified (issue 27;
  // docs/guide.md, "The local gravity"); the report_test of a verified one is in verdict_test.cpp.
  EXPECT_EQ(BuildReportModel(in).verdict, Verdict::kIncomplete);
  in.calibration.gravity = GravitySpec::Standard();
  const ReportModel m = BuildReportModel(in);
  EXPECT_EQ(m.verdict, Verdict::kIncomplete);
  ASSERT_EQ(m.incomplete.size(), 1u);
  EXPECT_TRUE(Contains(m.incomplete[0], "gravity not established")) << m.incomplete[0];
  EXPECT_TRUE(Contains(GravityAmbiguityNote(GravitySpec::Standard(), {"rpm_scale"}),
                       "the data cannot tell a gravity error from a speed or radius error"));
  // Whatever the gravity's source (issue 27, item 4): the data cannot tell them apart.
  EXPECT_TRUE(Contains(GravityAmbiguityNote(GravitySpec::Given(9.7803, 1e-5), {"rpm_scale"}),
                       "the data cannot tell a gravity error from a speed or radius error"));
  EXPECT_EQ(GravityAmbiguityNote(GravitySpec::Standard(), {"bias_drift"}), "");
}

// The same scale found and declined: the base model carries the gravity error in its scales,
// and the calibration file shows no effect; the session's gaps remember the finding.
TEST(ReportModel, ASpeedScaleDeclinedOnTheStandardGravityIsIncompleteToo) {
  ReportInputs in = FixtureInputs();
  in.calibration.gravity = GravitySpec::Standard();
  in.gaps = SessionGaps{};
  EXPECT_EQ(BuildReportModel(in).verdict, Verdict::kPass);  // nothing found: standard is fine
  in.gaps->gravity_ambiguity = GravityAmbiguityNote(GravitySpec::Standard(), {"rpm_scale"});
  ASSERT_FALSE(in.gaps->gravity_ambiguity.empty());
  const ReportModel m = BuildReportModel(in);
  EXPECT_EQ(m.verdict, Verdict::kIncomplete);
  ASSERT_EQ(m.incomplete.size(), 1u);
  EXPECT_TRUE(Contains(m.incomplete[0], "gravity not established")) << m.incomplete[0];
}

TEST(ReportModel, FromSessionCapturesMeasuresNoiseAndTemperature) {
  sim::VirtualBench bench(sim::DefaultScenario());
  std::vector<Capture> captures = bench.SimulateCaptureSet();
  // Give the samples a known temperature ramp: 20 + i/1000 degC over the whole session.
  double lo = INFINITY, hi = -INFINITY;
  long k = 0;
  for (Capture& c : captures)
    for (Sample& s : c.samples) {
      s.temp_c = 20.0 + static_cast<double>(k++) / 1000.0;
      lo = std::min(lo, s.temp_c);
      hi = std::max(hi, s.temp_c);
    }
  FitOptions fit;
  const FitSummary summary = FitCalibration(captures, fit);
  ASSERT_TRUE(summary.IsUsable()) << summary.message;
  ReportInputs in;
  in.calibration = MakeCalibration(summary, fit.gravity, captures, "sim");
  in.captures = ReportStatsOf(captures);
  ReportModel m = BuildReportModel(in);
  EXPECT_DOUBLE_EQ(m.temp_min_c, lo);
  EXPECT_DOUBLE_EQ(m.temp_max_c, hi);
  // Noise of capture 1: RMS over the axes of the samples' standard deviation.
  const Capture& c0 = captures[0];
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), var = Eigen::Vector3d::Zero();
  for (const Sample& s : c0.samples) mean += s.raw_counts;
  mean /= static_cast<double>(c0.samples.size());
  for (const Sample& s : c0.samples) var += (s.raw_counts - mean).cwiseAbs2();
  var /= static_cast<double>(c0.samples.size() - 1);
  EXPECT_NEAR(m.captures[0].noise_counts, std::sqrt(var.sum() / 3.0), 1e-9);
  // One stage (no effect): the calibration's own residuals.
  ASSERT_EQ(m.stages.size(), 1u);
  for (size_t i = 0; i < m.captures.size(); ++i) {
    if (m.captures[i].record.used) {
      EXPECT_NEAR(m.stages[0].residual_mps2[i], m.captures[i].record.residual_mps2, 1e-9);
    }
  }
}

TEST(ReportModel, StagesAreTheDiagnosisResidualsNotARefit) {
  // A bench with a drift: the pipeline adopts bias_drift; the calibration carries each capture's
  // residual under the base model and after the effect, and the report shows those stages.
  sim::Scenario scenario = sim::DefaultScenario();
  scenario.effects.temperature.reset();  // constant temperature: the drift is in time only
  scenario.effects.bias_drift_counts_per_s = {0.01, -0.01, 0.01};
  sim::VirtualBench bench(scenario);
  CalibrationRequest request;
  request.captures = bench.SimulateCaptureSet();
  request.source_name = "sim";
  const CalibrationOutcome outcome = CalibrateCaptures(request);
  ASSERT_TRUE(outcome.usable());
  ASSERT_EQ(outcome.diagnosis.adopted_names(), std::vector<std::string>{"bias_drift"});
  ReportInputs in;
  in.calibration = outcome.MakeCalibration(true);
  in.captures = ReportStatsOf(outcome.captures);
  const ReportModel m = BuildReportModel(in);
  ASSERT_EQ(m.stages.size(), 2u);
  EXPECT_EQ(m.stages[0].name, "base model");
  EXPECT_EQ(m.stages[1].name, "+ bias_drift");
  EXPECT_LE(m.stages[1].rms_mps2, m.stages[0].rms_mps2 + 1e-12);
  for (size_t i = 0; i < m.captures.size(); ++i) {
    const CaptureResidual* base = nullptr;
    for (const CaptureResidual& r : outcome.diagnosis.base.residuals)
      if (r.id == m.captures[i].record.id) base = &r;
    ASSERT_NE(base, nullptr);
    EXPECT_EQ(m.stages[0].residual_mps2[i], base->residual_mps2);
    EXPECT_EQ(m.stages[1].residual_mps2[i], m.captures[i].record.residual_mps2);
  }
  // The same from the file: the stages travel with the calibration.
  const ReportModel from_file = BuildReportModel(
      {CalibrationFromJsonText(CalibrationToJsonText(in.calibration), "c.json"), {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}});
  ASSERT_EQ(from_file.stages.size(), 2u);
  EXPECT_EQ(from_file.stages[1].residual_mps2, m.stages[1].residual_mps2);
}

TEST(ReportModel, MetaFromJournalInputs) {
  ReportMeta meta;
  FillMetaFromInputs({{"session", {{"device", "D1"}}}, {"welcome", {{"operator", "Ann"}, {"place", "Lab"}}}}, &meta);
  EXPECT_EQ(meta.device, "D1");
  EXPECT_EQ(meta.operator_name, "Ann");
  EXPECT_EQ(meta.place, "Lab");
  EXPECT_EQ(ReportPathFor("/a/b/s1.db", "html"), "/a/b/s1.report.html");
  EXPECT_EQ(ReportPathFor("s1", "txt"), "s1.report.txt");
}

// ---- text ------------------------------------------------------------------------------

TEST(ReportText, MatchesTheGoldenFile) {
  const std::string text = RenderReportText(FixtureModel());
  const std::string golden_path = kDataDir + "golden_report.txt";
  if (std::getenv("ACCELCAL_UPDATE_GOLDEN") != nullptr) {
    std::ofstream(golden_path, std::ios::binary) << text;
    GTEST_SKIP() << "golden file rewritten: " << golden_path;
  }
  EXPECT_EQ(text, ReadText(golden_path)) << "to accept a deliberate change: ACCELCAL_UPDATE_GOLDEN=1";
}

TEST(ReportText, EightyColumnsAsciiAndNotRecorded) {
  ReportInputs in = FixtureInputs();
  in.meta = ReportMeta();
  in.meta.device = std::string(150, 'D') + "\x1b[31m";
  std::string text = RenderReportText(BuildReportModel(in));
  std::istringstream lines(text);
  std::string line;
  int n = 0;
  while (std::getline(lines, line)) {
    ++n;
    EXPECT_LE(line.size(), 80u) << "line " << n << ": " << line;
    for (char c : line) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "line " << n << ": " << line;
  }
  EXPECT_TRUE(Contains(text, "\n  Operator:           not recorded\n"));
  EXPECT_TRUE(Contains(text, "\\x1B[31m"));  // the escape character made visible, not sent
}

// ---- HTML ------------------------------------------------------------------------------

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

TEST(ReportHtml, EscapesEverythingTheUserTyped) {
  ReportInputs in = FixtureInputs();
  in.meta.device = "<script>alert(1)</script>";
  in.meta.operator_name = "&\"'";
  in.meta.place = "<img src=x onerror=alert(2)>";
  const std::string html = RenderReportHtml(BuildReportModel(in));
  EXPECT_TRUE(Contains(html, "&lt;script&gt;alert(1)&lt;/script&gt;"));
  EXPECT_TRUE(Contains(html, "&amp;&quot;&#39;"));
  EXPECT_TRUE(Contains(html, "&lt;img src=x onerror=alert(2)&gt;"));
  // The fixture's left-out capture label and the fit source carry < > & " ' too.
  EXPECT_TRUE(Contains(html, "+z up (bumped) &lt;b&gt;&amp;&quot;&#39;"));
  EXPECT_TRUE(Contains(html, "fixture &lt;session&gt;.db"));
  EXPECT_FALSE(Contains(Lower(html), "<script"));
  EXPECT_FALSE(Contains(Lower(html), "<img"));
  EXPECT_FALSE(Contains(html, "(bumped) <b>"));
}

TEST(ReportHtml, SelfContainedWithPrintStylesheetAndPlots) {
  const std::string html = RenderReportHtml(FixtureModel());
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_FALSE(Contains(Lower(html), "http:"));
  EXPECT_FALSE(Contains(Lower(html), "https:"));
  EXPECT_FALSE(Contains(Lower(html), "url("));
  EXPECT_FALSE(Contains(Lower(html), "<link"));
  EXPECT_TRUE(Contains(html, "@media print"));
  // Residuals, magnitudes, Allan deviation.
  size_t svgs = 0;
  for (size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) ++svgs;
  EXPECT_EQ(svgs, 3u);
  EXPECT_TRUE(Contains(html, "Allan deviation"));
  EXPECT_TRUE(Contains(html, "x: N 0.0021"));  // read-off marked on the plot
  EXPECT_TRUE(Contains(html, "PASS"));
  // Deterministic.
  EXPECT_EQ(html, RenderReportHtml(FixtureModel()));
}

TEST(ReportHtml, WithoutAllanNoThirdPlotAndNotRecorded) {
  ReportInputs in = FixtureInputs();
  in.allan.reset();
  in.meta.place.clear();
  const std::string html = RenderReportHtml(BuildReportModel(in));
  size_t svgs = 0;
  for (size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) ++svgs;
  EXPECT_EQ(svgs, 2u);
  EXPECT_TRUE(Contains(html, "<th>Place</th><td><span class=\"absent\">not recorded</span>"));
}

// ---- JSON ------------------------------------------------------------------------------

TEST(ReportJson, ParsesBackToTheModelsFigures) {
  const ReportModel m = FixtureModel();
  const json j = json::parse(ReportToJson(m).dump());
  EXPECT_EQ(j["format"], kReportFormat);
  EXPECT_EQ(j["device"], m.meta.device);
  EXPECT_EQ(j["verdict"], "PASS");
  ASSERT_EQ(j["parameters"].size(), 9u);
  for (size_t i = 0; i < 9; ++i) {
    EXPECT_EQ(j["parameters"][i]["value"].get<double>(), m.parameters[i].value);
    EXPECT_EQ(j["parameters"][i]["sigma"].get<double>(), m.parameters[i].sigma);
  }
  ASSERT_EQ(j["captures"].size(), m.captures.size());
  EXPECT_TRUE(j["captures"].back()["residual_mps2"].is_null());
  EXPECT_EQ(j["captures"].back()["reason"], m.captures.back().record.reason);
  EXPECT_EQ(j["residuals"]["rms_mps2"].get<double>(), m.residual_rms_mps2);
  EXPECT_EQ(j["limits"].size(), m.checks.size());
  // The analyses go back through their own strict readers unchanged.
  const AllanSection a = ParseAllanJson(j["allan"], "report");
  EXPECT_EQ(a.axes[2]->adev, m.allan->axes[2]->adev);
  const NoiseSection n = ParseNoiseJson(j["noise"], "report");
  EXPECT_EQ(n.axes[1]->noise_density, m.noise->axes[1]->noise_density);
  // Absent: null, not a made-up value.
  ReportInputs bare;
  bare.calibration = ReadCalibrationFile(kDataDir + "calibration.json");
  const json b = ReportToJson(BuildReportModel(bare));
  EXPECT_TRUE(b["device"].is_null());
  EXPECT_TRUE(b["allan"].is_null());
  EXPECT_TRUE(b["temperature_c"]["min"].is_null());
  EXPECT_EQ(b["verdict"], "NO LIMITS STATED");
}

// ---- SVG -------------------------------------------------------------------------------

TEST(SvgPlot, TicksAndLabels) {
  const std::vector<double> t = LinearTicks(0.0, 1.0, 5);
  ASSERT_EQ(t.size(), 6u);
  EXPECT_NEAR(t[3], 0.6, 1e-12);
  const std::vector<double> l = LogTicks(0.003, 20.0);
  ASSERT_EQ(l.size(), 6u);  // 1e-3 .. 1e2
  EXPECT_DOUBLE_EQ(l.front(), 1e-3);
  EXPECT_DOUBLE_EQ(l.back(), 100.0);
  EXPECT_EQ(TickLabel(0.0), "0");
  EXPECT_EQ(TickLabel(0.05), "0.05");
  EXPECT_EQ(TickLabel(1e-4), "1e-04");
  EXPECT_EQ(TickLabel(-2.0), "-2");
  EXPECT_EQ(EscapeXml("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
}

TEST(SvgPlot, DrawsSeriesBandMarksAndSkipsBadPoints) {
  SvgPlotOptions o;
  o.title = "t <1>";
  o.log_x = o.log_y = true;
  SvgPlot p(o);
  SvgSeries s;
  s.name = "x";
  s.x = {0.1, 1.0, 10.0, -1.0};
  s.y = {1.0, 0.5, 0.2, 0.3};
  s.band_lo = {0.8, 0.4, 0.1, 0.2};
  s.band_hi = {1.2, 0.6, 0.3, 0.4};
  p.Add(s);
  p.Mark({1.0, 0.5, "N"});
  const std::string svg = p.Render();
  EXPECT_TRUE(Contains(svg, "t &lt;1&gt;"));
  EXPECT_TRUE(Contains(svg, "<polyline"));
  EXPECT_TRUE(Contains(svg, "fill-opacity=\"0.18\""));
  EXPECT_TRUE(Contains(svg, ">N</text>"));
  EXPECT_FALSE(Contains(svg, "nan"));
  EXPECT_FALSE(Contains(svg, "inf"));
  EXPECT_FALSE(Contains(svg, "http"));
  // The polyline has the three usable points only (x = -1 cannot be on a log axis).
  const size_t at = svg.find("<polyline points=\"");
  const std::string points = svg.substr(at + 18, svg.find('"', at + 18) - at - 18);
  EXPECT_EQ(std::count(points.begin(), points.end(), ','), 3);
  EXPECT_EQ(svg, p.Render());
  SvgPlot empty(SvgPlotOptions{});
  EXPECT_TRUE(Contains(empty.Render(), "no data"));
}

// ---- procedure limits ------------------------------------------------------------------

constexpr const char* kProcedureHead = R"(title = "t"
[sensor]
nominal_scale_counts_per_mps2 = 34.8
nominal_bias_counts = 2048
)";
// After the [limits] table (a TOML table runs to the next header).
constexpr const char* kProcedureSteps = "[[step]]\nid = \"fit\"\nkind = \"fit\"\n";

TEST(ProcedureLimits, ParsedValidatedAndOptional) {
  const Procedure none = ParseProcedure(std::string(kProcedureHead) + kProcedureSteps, "p.toml");
  EXPECT_FALSE(none.limits.Any());
  const Procedure p = ParseProcedure(std::string(kProcedureHead) +
                                         "[limits]\nmin_captures = 12\nmax_residual_rms_mps2 = 0.02\n"
                                         "max_scale_U_ppm = 500\n" + kProcedureSteps,
                                     "p.toml");
  EXPECT_TRUE(p.limits.Any());
  EXPECT_EQ(p.limits.min_captures, 12);
  EXPECT_EQ(p.limits.max_residual_rms_mps2, 0.02);
  EXPECT_EQ(p.limits.max_scale_U_ppm, 500.0);
  EXPECT_TRUE(std::isnan(p.limits.max_bias_U_counts));
  EXPECT_EQ(p.limits.decision_rule, DecisionRule::kSimpleAcceptance);  // the default
  EXPECT_TRUE(p.limits.converted.empty());
  const InputError e = ExpectInputError(
      [] { ParseProcedure(std::string(kProcedureHead) + "[limits]\nmax_residual_rms = 0.02\n" + kProcedureSteps, "p.toml"); }, "typo");
  EXPECT_TRUE(Contains(e.what(), "max_residual_rms")) << e.what();
  ExpectInputError([] { ParseProcedure(std::string(kProcedureHead) + "[limits]\nmax_bias_sigma_counts = -1\n" + kProcedureSteps, "p.toml"); },
                   "negative");
  ExpectInputError([] { ParseProcedure(std::string(kProcedureHead) + "[limits]\nmin_captures = -3\n" + kProcedureSteps, "p.toml"); },
                   "negative count");
  const Procedure seed = LoadProcedure(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/full_calibration.toml");
  EXPECT_EQ(seed.limits.min_captures, 15);
  EXPECT_TRUE(seed.limits.Any());
}

}  // namespace
}  // namespace accelcal::report_test
