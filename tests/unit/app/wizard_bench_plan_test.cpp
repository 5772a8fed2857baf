// The capture plan in the wizard (app/wizard/bench_plan.h) on the virtual bench: the welcome says
// the bench time of the plan; each capture ends on the sample count the plan fixed before it
// started (whole revolutions on the turntable); the plan is made again when the measured noise
// floor differs from the procedure's expected noise; --fixed-duration keeps fixed captures; the
// bench time spent and planned, and the planned and reached U, are in the report's JSON.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "accelcal/app/report_inputs.h"
#include "accelcal/io/report_json.h"
#include "accelcal/report/bench_time.h"
#include "wizard_test_support.h"

namespace accelcal::wizard_bench_plan_test {
namespace {

using testing::AcceptUntil;
using testing::FullProcedure;
using testing::Never;
using testing::WizardRig;

double InputNumber(const SessionJournal& j, const std::string& step, const std::string& key) {
  return std::stod(j.Inputs().at(step).at(key));
}

TEST(WizardBenchPlan, CapturesEndOnThePlansCountAndTheReportStatesTheBenchTime) {
  WizardRig rig(FullProcedure(), sim::DefaultScenario());
  const WizardView welcome = rig.engine.View();
  EXPECT_NE(welcome.prompt.find("This plan reaches the procedure's target in"), std::string::npos) << welcome.prompt;
  // The welcome's default gravity is the standard one: no capture length buys the scale's target.
  EXPECT_NE(welcome.prompt.find("No capture length reaches the target on"), std::string::npos) << welcome.prompt;
  EXPECT_NE(welcome.prompt.find("scale_x"), std::string::npos) << welcome.prompt;
  AcceptUntil(rig.engine, Never);
  ASSERT_TRUE(rig.engine.View().finished);
  const SessionJournal& j = *rig.journal;
  ASSERT_EQ(j.Captures().size(), 18u);
  for (const JournalCapture& c : j.Captures()) {
    const size_t n = c.capture.samples.size();
    EXPECT_LE(n, 1000u) << c.step_id << ": no longer than the fixed 10 s";
    if (c.capture.kind == CaptureKind::kTurntable) {
      EXPECT_EQ(n % 50, 0u) << c.step_id << ": whole revolutions";
    }
    EXPECT_NEAR(InputNumber(j, c.step_id, "capture_s"), static_cast<double>(n) / 100.0, 0.011) << c.step_id;
  }
  const std::optional<ReportBenchTime> bench = BenchTimeFromInputs(j.Inputs());
  ASSERT_TRUE(bench.has_value());
  EXPECT_EQ(bench->planned_by, "target");
  EXPECT_EQ(bench->captures, 18);
  EXPECT_DOUBLE_EQ(bench->spent.handling_s, 18 * 20.0 + 3 * 60.0);  // the virtual bench's handling model
  EXPECT_DOUBLE_EQ(bench->planned.handling_s, bench->spent.handling_s);
  // The counts are the plan's, rounded up to whole samples and revolutions.
  EXPECT_GE(bench->spent.capture_s, bench->planned.capture_s - 0.1);
  EXPECT_LE(bench->spent.capture_s, bench->planned.capture_s + 18 * 0.5);
  EXPECT_LE(bench->planned.capture_s, 180.0);

  const ReportModel model = BuildReportModel(ReportInputsFromJournal(j, "session"));
  const nlohmann::json report = nlohmann::json::parse(ReportJsonText(model));
  const nlohmann::json& bt = report.at("bench_time");
  for (const char* key : {"capture_s", "settle_s", "handling_s", "total_s"}) EXPECT_TRUE(bt.at(key).is_number()) << key;
  EXPECT_NEAR(bt.at("total_s").get<double>(), bench->spent.TotalS(), 1e-6);
  EXPECT_NEAR(bt.at("planned").at("total_s").get<double>(), bench->planned.TotalS(), 1e-6);
  const nlohmann::json& bias_x = bt.at("uncertainty").at(0);
  EXPECT_EQ(bias_x.at("name"), "bias_x");
  EXPECT_TRUE(bias_x.at("planned_U").is_number());
  EXPECT_TRUE(bias_x.at("reached_U").is_number());
  // The reached U is what the plan predicted, within the fit's scatter.
  EXPECT_NEAR(bias_x.at("reached_U").get<double>() / bias_x.at("planned_U").get<double>(), 1.0, 0.25);
}

TEST(WizardBenchPlan, FixedDurationKeepsFixedCaptures) {
  WizardOptions options{"test", "op", "SN1", {}, 2.0, {}};
  options.fixed_duration_s = 4.0;
  WizardRig rig(FullProcedure(), sim::DefaultScenario(), nullptr, options);
  EXPECT_NE(rig.engine.View().prompt.find("(4 s captures, handling included)"), std::string::npos)
      << rig.engine.View().prompt;
  AcceptUntil(rig.engine, Never);
  ASSERT_TRUE(rig.engine.View().finished);
  for (const JournalCapture& c : rig.journal->Captures()) EXPECT_EQ(c.capture.samples.size(), 400u) << c.step_id;
  EXPECT_EQ(rig.journal->Inputs().at("bench_plan").at("planned_by"), "fixed");
}

TEST(WizardBenchPlan, TheMeasuredNoiseFloorPlansAgain) {
  // The procedure expects twice the default sensor's noise: the welcome's plan is not the one
  // the measured floor gives, and the captures follow the latter.
  Procedure p = FullProcedure();
  p.expected_noise_counts = Eigen::Vector3d::Constant(3.0);
  WizardRig rig(p, sim::DefaultScenario());
  (void)rig.engine.View();
  const double at_welcome = InputNumber(*rig.journal, "bench_plan", "planned_capture_s");
  AcceptUntil(rig.engine, Never);
  ASSERT_TRUE(rig.engine.View().finished);
  const double measured = InputNumber(*rig.journal, "bench_plan", "planned_capture_s");
  EXPECT_GT(std::abs(measured - at_welcome), 0.05 * at_welcome) << at_welcome << " " << measured;
  const std::optional<ReportBenchTime> bench = BenchTimeFromInputs(rig.journal->Inputs());
  ASSERT_TRUE(bench.has_value());
  EXPECT_NEAR(bench->spent.capture_s, measured, 18 * 0.5);
}

}  // namespace
}  // namespace accelcal::wizard_bench_plan_test
