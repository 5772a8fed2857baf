// The closing repeat pose (kind "repeat", app/wizard/steps/repeat_step.cpp): the full procedure
// takes its first pose again at the end, the capture goes into the fit, and the wizard says how
// far the reading moved against the noise. The kind is defined only in its controller's file and
// registered by one line (step_registry.cpp); the procedure reader knows it once registered
// (test_main.cpp, as the program's main).
#include <string>

#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/base/error.h"
#include "accelcal/io/procedure_file.h"
#include "wizard_test_support.h"

namespace accelcal {
namespace {

std::string Shipped(const std::string& name) { return std::string(ACCELCAL_SOURCE_DIR) + "/procedures/" + name; }

int Count(const Procedure& p, std::string_view kind) {
  int n = 0;
  for (const ProcedureStep& s : p.steps) n += StepKindToString(s.kind) == kind;
  return n;
}

// Moved here from io's procedure_test: the full procedure has a step of a kind the wizard defines.
TEST(ProcedureTest, FullCalibrationLoads) {
  const Procedure p = LoadProcedure(Shipped("full_calibration.toml"));
  EXPECT_EQ(p.title, "Full calibration: level, 9 prism poses, 9 turntable runs, fit, diagnosis");
  // Its title before the rename (seed_calibration.toml): sessions recorded under it are its.
  EXPECT_TRUE(p.IsTitled("Seed calibration: level, 9 prism poses, 9 turntable runs, fit, diagnosis"));
  EXPECT_TRUE(p.IsTitled(p.title));
  EXPECT_FALSE(p.IsTitled("Full calibration"));
  EXPECT_EQ(Count(p, "level"), 1);
  EXPECT_EQ(Count(p, "static"), 9);
  EXPECT_EQ(Count(p, "turntable"), 9);
  EXPECT_EQ(Count(p, "repeat"), 1);
  EXPECT_EQ(Count(p, "fit"), 1);
  EXPECT_EQ(Count(p, "diagnosis"), 1);
  EXPECT_EQ(Count(p, "report"), 1);
  EXPECT_DOUBLE_EQ(p.range_g, 6.0);
  EXPECT_DOUBLE_EQ(p.nominal.scale_counts_per_mps2.x(), 34.8);
  EXPECT_DOUBLE_EQ(p.adc_range.max_counts, 4095.0);
  EXPECT_EQ(p.TiltedPoses().size(), 3u);
  const ProcedureStep& tt = p.steps[10];
  EXPECT_EQ(tt.kind, StepKind::kTurntable);
  EXPECT_DOUBLE_EQ(tt.radius_m, 0.05);
  EXPECT_DOUBLE_EQ(tt.rpm, 120.0);
  EXPECT_EQ(tt.pose_name, "+x radial, +z up");
  EXPECT_DOUBLE_EQ(tt.duration_s, 10.0);
}

TEST(RepeatStep, TakesTheEarlierPoseAndIsACaptureForTheFit) {
  const Procedure p = LoadProcedure(Shipped("full_calibration.toml"));
  const ProcedureStep* first = nullptr;
  const ProcedureStep* again = nullptr;
  for (const ProcedureStep& s : p.steps) {
    if (s.id == "pose_pz") first = &s;
    if (StepKindToString(s.kind) == "repeat") again = &s;
  }
  ASSERT_NE(first, nullptr);
  ASSERT_NE(again, nullptr);
  EXPECT_EQ(again->id, "repeat_pz");
  EXPECT_EQ(again->title, "+z up again");
  EXPECT_EQ(again->pose_name, first->pose_name);
  EXPECT_TRUE(again->up.isApprox(first->up));
  EXPECT_DOUBLE_EQ(again->duration_s, first->duration_s);
  EXPECT_DOUBLE_EQ(again->timeout_s, first->timeout_s);
  EXPECT_TRUE(KeepsCapture(again->kind));
  EXPECT_TRUE(IsStaticPoseStep(again->kind));
  EXPECT_TRUE(InfoOf(again->kind).skippable);
  // The last step before the fit.
  EXPECT_EQ(StepKindToString((again + 1)->kind), "fit");
}

constexpr const char* kTwoPoses = R"(
title = "t"
[sensor]
nominal_scale_counts_per_mps2 = 34.8
nominal_bias_counts = 2048
[[step]]
id = "pose_pz"
kind = "static"
up = [0, 0, 1]
pose = "+z up"
[[step]]
id = "tt"
kind = "turntable"
radius_m = 0.1
rpm = 120
[[step]]
id = "again"
kind = "repeat"
of = "OF"
)";

std::string Refusal(const std::string& of) {
  std::string text = kTwoPoses;
  text.replace(text.find("OF"), 2, of);
  try {
    ParseProcedure(text, "p.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(RepeatStep, OfMustNameAnEarlierStaticPose) {
  EXPECT_EQ(Refusal("pose_pz"), "accepted");
  EXPECT_NE(Refusal("tt").find("step 3.of: 'tt' is not an earlier static pose"), std::string::npos) << Refusal("tt");
  EXPECT_NE(Refusal("again").find("'again' is not an earlier static pose"), std::string::npos);
  EXPECT_NE(Refusal("nowhere").find("'nowhere' is not an earlier static pose"), std::string::npos);
  std::string no_of = kTwoPoses;
  no_of.replace(no_of.find("of = \"OF\""), 9, "");
  try {
    ParseProcedure(no_of, "p.toml");
    FAIL() << "a repeat without `of` was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("step 3.of: required key is missing"), std::string::npos) << e.what();
  }
  std::string own_pose = kTwoPoses;
  own_pose.replace(own_pose.find("of = \"OF\""), 9, "of = \"pose_pz\"\nup = [1, 0, 0]");
  EXPECT_THROW(ParseProcedure(own_pose, "p.toml"), InputError);  // its pose is the earlier step's
}

bool AtRepeat(const WizardView& v) { return v.step_title == "+z up again"; }
bool AtFit(const WizardView& v) { return v.step_title == "Fit the nine-parameter model"; }

TEST(RepeatStep, AStillSensorReadsAsBeforeAndTheSessionPasses) {
  testing::WizardRig rig(testing::FullProcedure(), sim::DefaultScenario());
  testing::AcceptUntil(rig.engine, AtRepeat);
  const WizardView place = rig.engine.View();
  EXPECT_EQ(place.prompt, "Put the prism on the table with +z up again, as for the first pose, and let go: "
                          "what moved since is measured. Press Enter to capture.");
  rig.engine.Handle({IntentKind::kAccept, ""});
  testing::AcceptUntil(rig.engine, AtFit);
  const std::string notice = rig.engine.View().notice;
  EXPECT_NE(notice.find("+z up done:"), std::string::npos) << notice;
  EXPECT_NE(notice.find("; since the first time the reading moved "), std::string::npos) << notice;
  EXPECT_NE(notice.find("within its noise"), std::string::npos) << notice;
  testing::AcceptUntil(rig.engine, testing::Never);
  EXPECT_EQ(rig.journal->Captures().size(), 19u);
  EXPECT_EQ(rig.engine.View().verdict, "PASS");
}

TEST(RepeatStep, ADriftIsMeasuredAndSaid) {
  sim::Scenario drifting = sim::DefaultScenario();
  drifting.effects.bias_drift_counts_per_s = Eigen::Vector3d(0.0, 0.0, 0.01);  // 6 counts in 10 min
  testing::WizardRig rig(testing::FullProcedure(), drifting);
  testing::AcceptUntil(rig.engine, AtFit);
  const std::string notice = rig.engine.View().notice;
  EXPECT_NE(notice.find("; since the first time the reading moved "), std::string::npos) << notice;
  EXPECT_NE(notice.find("more than its noise"), std::string::npos) << notice;
}

}  // namespace
}  // namespace accelcal
