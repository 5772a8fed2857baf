// The capture plan in the wizard (app/wizard/bench_plan.h) on the virtual bench: the welcome says
// the bench time of the plan; each capture ends on the sample count the plan fixed before it
// started (whole revolutions on the turntable); the plan is made again when the measured noise
// floor differs from the procedure's expected noise; --fixed-duration keeps fixed captures; the
// bench time spent and planned, and the planned and reached U, are in the report's JSON.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "accelcal/app/report_inputs.h"
#include "accelcal/app/wizard/bench_plan.h"
#include "accelcal/app/wizard/resume_summary.h"
#include "accelcal/io/report_json.h"
#include "accelcal/io/scenario_file.h"
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
  // 9 poses, 9 runs, the first pose again twice on the stopped turntable and at the end.
  ASSERT_EQ(j.Captures().size(), 21u);
  for (const JournalCapture& c : j.Captures()) {
    const size_t n = c.capture.samples.size();
    // The virtual lab's equipment leaves some targets within reach: captures may be longer than
    // the fixed 10 s, never than the procedure's max_capture_s (60 s, and a revolution more).
    EXPECT_LE(n, 6100u) << c.step_id << ": no longer than max_capture_s";
    if (c.capture.kind == CaptureKind::kTurntable) {
      EXPECT_EQ(n % 50, 0u) << c.step_id << ": whole revolutions";
    }
    EXPECT_NEAR(InputNumber(j, c.step_id, "capture_s"), static_cast<double>(n) / 100.0, 0.011) << c.step_id;
  }
  const std::optional<ReportBenchTime> bench = BenchTimeFromInputs(j.Inputs());
  ASSERT_TRUE(bench.has_value());
  EXPECT_EQ(bench->planned_by, "target");
  EXPECT_EQ(bench->captures, 21);
  EXPECT_DOUBLE_EQ(bench->spent.handling_s, 21 * 20.0 + 3 * 60.0);  // the virtual bench's handling model
  EXPECT_DOUBLE_EQ(bench->planned.handling_s, bench->spent.handling_s);
  // The counts are the plan's, rounded up to whole samples and revolutions.
  EXPECT_GE(bench->spent.capture_s, bench->planned.capture_s - 0.1);
  EXPECT_LE(bench->spent.capture_s, bench->planned.capture_s + 21 * 0.5);
  EXPECT_LE(bench->planned.capture_s, 21 * 60.0);

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
  EXPECT_NEAR(bench->spent.capture_s, measured, 21 * 0.5);
}

// The optional captures the plan leaves out (they buy nothing for this sensor) are skipped, said
// on the way; the session's time left counts the plan's lengths and not the steps left out.
TEST(WizardBenchPlan, OptionalCapturesThePlanLeavesOutAreSkipped) {
  Procedure p = FullProcedure();
  p.target = ProcedureTarget{};
  p.target.bias_mg = 5.0;  // a target the bias reaches without every run
  p.limits.min_captures = 9;
  for (ProcedureStep& s : p.steps)
    if (InfoOf(s.kind).acquires == StepAcquires::kTurntableCapture) s.required = false;
  WizardRig rig(p, sim::DefaultScenario());
  (void)rig.engine.View();
  std::vector<std::string> notices;
  for (int i = 0; i < 2000 && !rig.engine.View().finished; ++i) {
    testing::PollUntilQuestion(rig.engine);
    const WizardView v = rig.engine.View();
    if (v.notice.find("skipped: the capture plan leaves") != std::string::npos) notices.push_back(v.notice);
    if (v.finished) break;
    rig.engine.Handle({IntentKind::kAccept, ""});
  }
  ASSERT_TRUE(rig.engine.View().finished);

  const SessionJournal& j = *rig.journal;
  const std::map<std::string, std::string> done = j.DoneSteps();
  int skipped = 0;
  for (const ProcedureStep& s : p.steps) {
    if (InfoOf(s.kind).acquires != StepAcquires::kTurntableCapture) continue;
    const std::vector<JournalCapture> captures = j.Captures();
    const bool captured = std::any_of(captures.begin(), captures.end(),
                                      [&](const JournalCapture& c) { return c.step_id == s.id; });
    if (done.count(s.id) && done.at(s.id) == "skipped") {
      ++skipped;
      EXPECT_FALSE(captured) << s.id;
    }
  }
  EXPECT_GT(skipped, 0) << "the plan left nothing out";
  for (const ProcedureStep& s : p.steps) {
    if (done.count(s.id) && done.at(s.id) == "skipped") {
      EXPECT_TRUE(testing::AnyContains(notices, "'" + StepDisplayTitle(s) + "'")) << s.id << " skipped unsaid; said: " << ::testing::PrintToString(notices);
    }
  }
  // A repeat on the stopped turntable after runs left out has no turntable to stand on: it is set
  // on the prism, as the first time, and taken.
  const std::vector<JournalCapture> captures = j.Captures();
  for (const auto& [run, repeat] : {std::pair{"tt_x_150", "repeat_pz_after_x"}, std::pair{"tt_y_150", "repeat_pz_after_y"}})
    if (done.count(run) && done.at(run) == "skipped") {
      EXPECT_TRUE(std::any_of(captures.begin(), captures.end(),
                              [&](const JournalCapture& c) { return c.step_id == repeat; })) << repeat;
    }
  EXPECT_TRUE(j.Result().has_value());
}

// The welcome's bench time is the plan of the equipment its question offers (the virtual lab's:
// the ruler to 0.03 mm), which Enter keeps: the plan is not made again once it is answered (it
// was made with the procedure's example ruler, 0.5 mm: the demo's welcome said 14 min for 16).
TEST(WizardBenchPlan, TheWelcomePlansWithTheEquipmentEnterKeeps) {
  // The README's demo: the default scenario file, whose lab (gravity, equipment) the welcome offers.
  WizardRig rig(FullProcedure(), sim::LoadScenario(std::string(ACCELCAL_SOURCE_DIR) + "/scenarios/bench_default.toml"));
  (void)rig.engine.View();
  const double at_welcome = InputNumber(*rig.journal, "bench_plan", "planned_capture_s");
  // Past the first capture (its request is planned again with what the session holds then).
  AcceptUntil(rig.engine, [](const WizardView& v) { return v.step_title == "-z up" && v.screen == WizardScreen::kPlacePose; });
  EXPECT_DOUBLE_EQ(InputNumber(*rig.journal, "bench_plan", "planned_capture_s"), at_welcome);
}

// The give-up counts from the pose: the procedure's capture_timeout_s (60 s) for a capture the
// plan makes longer than the step's own 10 s, since a capture begun in time runs to its end; only
// a capture as long as that keeps the step's slack (50 s) after it.
TEST(WizardBenchPlan, APlannedCaptureGivesUpAtTheProceduresTimeout) {
  const Procedure p = FullProcedure();
  const ProcedureStep& pose = p.steps[1];
  ASSERT_EQ(pose.id, "pose_pz");
  EXPECT_DOUBLE_EQ(BenchPlan::GiveUpS(pose, 15.0), 60.0);
  EXPECT_DOUBLE_EQ(BenchPlan::GiveUpS(pose, 59.0), 60.0);
  EXPECT_DOUBLE_EQ(BenchPlan::GiveUpS(pose, 60.0), 110.0);

  WizardRig rig(p, sim::DefaultScenario());
  AcceptUntil(rig.engine, [](const WizardView& v) { return v.step_title == "+z up" && v.screen == WizardScreen::kPlacePose; });
  rig.engine.Handle({IntentKind::kAccept, ""});
  double longest_left_s = 0.0, latest_give_up_s = 0.0;
  for (int i = 0; i < 5000 && testing::Busy(rig.engine.View()); ++i) {
    const WizardView v = rig.engine.View();
    if (std::isfinite(v.capture_left_s)) longest_left_s = std::max(longest_left_s, v.capture_left_s);
    if (std::isfinite(v.give_up_in_s)) latest_give_up_s = std::max(latest_give_up_s, v.give_up_in_s);
    if (std::isfinite(v.give_up_in_s)) {
      EXPECT_TRUE(v.time_text.find("gives up in ") != std::string::npos) << v.time_text;
    }
    rig.engine.Poll(0.0);
  }
  EXPECT_GT(longest_left_s, pose.duration_s);  // the plan's capture, longer than the step's
  EXPECT_GT(latest_give_up_s, 50.0);
  EXPECT_LE(latest_give_up_s, pose.timeout_s);  // the first pose: no settling wait
}

// The capture screen's "session: about N min left" is the plan's: each capture as long as the
// plan has it, not the step's own 10 s.
TEST(WizardBenchPlan, TheSessionTimeLeftIsThePlans) {
  WizardOptions fixed_options{"test", "op", "SN1", {}, 2.0, {}};
  fixed_options.fixed_duration_s = 10.0;
  WizardRig planned(FullProcedure(), sim::DefaultScenario());
  WizardRig fixed(FullProcedure(), sim::DefaultScenario(), nullptr, fixed_options);
  const auto at_first_pose = [](const WizardView& v) { return v.step_title == "+z up" && v.screen == WizardScreen::kPlacePose; };
  AcceptUntil(planned.engine, at_first_pose);
  AcceptUntil(fixed.engine, at_first_pose);
  const double plan_capture_s = InputNumber(*planned.journal, "bench_plan", "planned_capture_s");
  const double fixed_capture_s = InputNumber(*fixed.journal, "bench_plan", "planned_capture_s");
  ASSERT_GT(std::abs(fixed_capture_s - plan_capture_s), 20.0);  // the plan's lengths are not 21 x 10 s
  // The difference of the two estimates is the difference of the capture lengths.
  EXPECT_NEAR(fixed.engine.View().session_left_s - planned.engine.View().session_left_s,
              fixed_capture_s - plan_capture_s, 15.0);
  // And the captures are counted as the welcome's plan counts them (each mounting once): the rest
  // of the session is the plan's bench time and the steps without a capture (the fit, the
  // diagnosis, the report: a reading each), not 9 mountings.
  const double plan_total_s = plan_capture_s + InputNumber(*planned.journal, "bench_plan", "planned_settle_s") +
                              InputNumber(*planned.journal, "bench_plan", "planned_handling_s");
  EXPECT_GE(planned.engine.View().session_left_s, plan_total_s);
  EXPECT_LE(planned.engine.View().session_left_s, plan_total_s + 120.0);
}

}  // namespace
}  // namespace accelcal::wizard_bench_plan_test
