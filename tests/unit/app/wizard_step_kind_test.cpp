// Adding a step kind the way ARCHITECTURE.md says ("How to add a step kind"): a kind defined only
// here, a pause for the technician ("pause": its `text` said and Enter goes on; its time estimate
// the `minutes` given), with its fields read from the procedure file by its own reader, its
// controller, and one registration (RegisterWizardStepKind). It runs through a session like the
// built-in kinds: the engine sequences it, skips it when asked twice, goes back from it to the
// capture before it, resumes at it, and records its outcome.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/app/wizard/step_controller.h"
#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/app/wizard/time_estimate.h"
#include "accelcal/app/wizard/wizard_session.h"
#include "accelcal/base/error.h"
#include "accelcal/io/procedure_file.h"
#include "wizard_test_support.h"

namespace accelcal {
namespace {

// ---- the example kind: everything it takes --------------------------------------------------

struct PauseFields final : StepOwnFields {
  std::string text;
  double minutes = 1.0;
};

void ReadPauseFields(StepFields& fields, ProcedureStep& step, const StepDefaults&) {
  auto own = std::make_shared<PauseFields>();
  own->text = fields.Text("text", std::nullopt);
  own->minutes = fields.Number("minutes", 1.0, FieldRange::kPositive);
  step.own_fields = std::move(own);
}

const PauseFields& PauseOf(const ProcedureStep& step) {
  return dynamic_cast<const PauseFields&>(*step.own_fields);
}

class PauseStep final : public StepController {
 public:
  PauseStep(const ProcedureStep& step, WizardSession& session) : step_(step), session_(session) {}
  void Enter() override {}
  void Handle(const Intent& intent) override {
    if (intent.kind == IntentKind::kSkip) return session_.sequence.AskSkip();
    if (intent.kind == IntentKind::kBack) return session_.sequence.GoBack();
    if (intent.kind == IntentKind::kAccept) session_.sequence.FinishStep("paused");
  }
  void KeepAfterSkipDeclined() override {}
  void SetHeader(WizardView& v) const override { v.step_title = step_.title; }
  void SetView(WizardView& v) const override {
    v.screen = WizardScreen::kPlacePose;
    v.prompt = PauseOf(step_).text + "; press Enter to go on.";
    v.keys = WithNavigation({{"Enter", "go on"}});
  }

 private:
  const ProcedureStep& step_;
  WizardSession& session_;
};

double PauseEstimateS(const ProcedureStep& step, const TimeAllowances&) { return 60.0 * PauseOf(step).minutes; }

// The one registration.
StepKind PauseKind() {
  static const StepKind kind = RegisterWizardStepKind(
      {"pause", StepAcquires::kNothing, true, false, "", &ReadPauseFields, nullptr},
      {StepKind{}, &MakeStepController<PauseStep>, &PauseEstimateS, nullptr, nullptr});
  return kind;
}

// ---- a session with it ----------------------------------------------------------------------

constexpr const char* kProcedure = R"(
title = "Two poses with a pause between them"
[sensor]
range_g = 6
nominal_scale_counts_per_mps2 = 34.8
nominal_bias_counts = 2048
adc_bits = 12
[checks]
capture_duration_s = 3
[[step]]
id = "pose_pz"
kind = "static"
up = [0, 0, 1]
pose = "+z up"
[[step]]
id = "tea"
kind = "pause"
title = "Let the bench cool"
text = "Leave the bench alone for five minutes"
minutes = 5
[[step]]
id = "pose_mz"
kind = "static"
up = [0, 0, -1]
pose = "-z up"
)";

Procedure PauseProcedure() {
  PauseKind();
  return ParseProcedure(kProcedure, "pause.toml");
}

bool AtPause(const WizardView& v) { return v.step_title == "Let the bench cool"; }

TEST(ExampleStepKind, IsInTheTableAndReadFromTheProcedureFile) {
  const Procedure p = PauseProcedure();
  ASSERT_EQ(p.steps.size(), 3u);
  EXPECT_EQ(p.steps[1].kind, PauseKind());
  EXPECT_EQ(StepKindToString(p.steps[1].kind), "pause");
  EXPECT_EQ(StringToStepKind("pause"), PauseKind());
  EXPECT_FALSE(UsesSensor(PauseKind()));
  EXPECT_FALSE(KeepsData(PauseKind()));
  EXPECT_EQ(PauseOf(p.steps[1]).text, "Leave the bench alone for five minutes");
  EXPECT_DOUBLE_EQ(PauseOf(p.steps[1]).minutes, 5.0);
  EXPECT_DOUBLE_EQ(StepEstimateS(p.steps[1]), 300.0);
  // Registering it again changes nothing.
  StepKindInfo again;
  again.name = "pause";
  again.acquires = StepAcquires::kStaticCapture;
  EXPECT_EQ(RegisterWizardStepKind(again, StepControllerKind()), PauseKind());
  EXPECT_EQ(InfoOf(PauseKind()).acquires, StepAcquires::kNothing);
}

TEST(ExampleStepKind, ItsFieldsAreCheckedLikeEveryStep) {
  PauseKind();
  std::string no_text = kProcedure;
  no_text.replace(no_text.find("text = "), std::string("text = \"Leave the bench alone for five minutes\"").size(), "");
  try {
    ParseProcedure(no_text, "pause.toml");
    FAIL() << "a pause without its text was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("step 2.text: required key is missing"), std::string::npos) << e.what();
  }
  std::string typo = kProcedure;
  typo.replace(typo.find("minutes = 5"), 11, "minuts = 5");
  EXPECT_THROW(ParseProcedure(typo, "pause.toml"), InputError);
}

TEST(ExampleStepKind, RunsThroughASession) {
  testing::WizardRig rig(PauseProcedure(), sim::DefaultScenario());
  testing::AcceptUntil(rig.engine, AtPause);
  WizardView v = rig.engine.View();
  EXPECT_EQ(v.prompt, "Leave the bench alone for five minutes; press Enter to go on.");
  EXPECT_EQ(v.step_index, 3);
  // The pause's own estimate is in the session's time left: its 5 min and the last pose.
  const TimeAllowances a;
  EXPECT_DOUBLE_EQ(v.session_left_s, 300.0 + a.place_pose_s + a.settle_s + 3.0);
  testing::AcceptUntil(rig.engine, testing::Never);
  EXPECT_TRUE(rig.engine.completed());
  EXPECT_EQ(rig.journal->DoneSteps().at("tea"), "paused");
  EXPECT_EQ(rig.journal->Captures().size(), 2u);
}

TEST(ExampleStepKind, IsSkippedWhenAskedTwiceAndLeftForTheWayBack) {
  testing::WizardRig rig(PauseProcedure(), sim::DefaultScenario());
  testing::AcceptUntil(rig.engine, AtPause);
  // b goes back to the capture before it: taking +z up again is offered; n keeps it.
  rig.engine.Handle({IntentKind::kBack, ""});
  EXPECT_NE(rig.engine.View().prompt.find("Take '+z up' again?"), std::string::npos) << rig.engine.View().prompt;
  rig.engine.Handle({IntentKind::kAnswerNo, ""});
  EXPECT_TRUE(AtPause(rig.engine.View()));
  // s asks first; Enter keeps the step; s twice skips it.
  rig.engine.Handle({IntentKind::kSkip, ""});
  EXPECT_NE(rig.engine.View().prompt.find("Skip 'Let the bench cool'?"), std::string::npos);
  rig.engine.Handle({IntentKind::kAccept, ""});
  EXPECT_TRUE(AtPause(rig.engine.View()));
  EXPECT_EQ(rig.journal->DoneSteps().count("tea"), 0u);
  rig.engine.Handle({IntentKind::kSkip, ""});
  rig.engine.Handle({IntentKind::kSkip, ""});
  EXPECT_EQ(rig.journal->DoneSteps().at("tea"), "skipped");
  EXPECT_EQ(rig.engine.View().step_title, "-z up");
}

TEST(ExampleStepKind, AResumedSessionGoesOnAtIt) {
  auto journal = std::shared_ptr<SessionJournal>(MakeMemoryJournal());
  {
    testing::WizardRig rig(PauseProcedure(), sim::DefaultScenario(), journal);
    testing::AcceptUntil(rig.engine, AtPause);
    rig.engine.Handle({IntentKind::kQuit, ""});
  }
  testing::WizardRig again(PauseProcedure(), sim::DefaultScenario(), journal);
  EXPECT_TRUE(AtPause(again.engine.View()));
  EXPECT_TRUE(again.engine.View().resumed);
  again.engine.Handle({IntentKind::kAccept, ""});
  EXPECT_EQ(journal->DoneSteps().at("tea"), "paused");
}

}  // namespace
}  // namespace accelcal
