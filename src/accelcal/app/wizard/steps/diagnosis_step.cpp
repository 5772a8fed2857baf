// The diagnosis (kind "diagnosis"): the effects the base model misses, said in plain words
// (diagnosis_words.h) with the recommended choice on Enter and the statistics on d; Enter adopts
// what it proposes, n keeps the base model. The choice goes to the report (and is read again on
// a resume from the step's outcome in the journal).
#include <fmt/format.h>

#include "accelcal/app/wizard/diagnosis_words.h"
#include "accelcal/app/wizard/session_settings.h"
#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/app/wizard/steps/result_step.h"

namespace accelcal {
namespace {

class DiagnosisStep final : public ResultStep {
 public:
  using ResultStep::ResultStep;

  // A diagnosis decided in an earlier run: adopted effects go into the report (read as
  // `accelcal refit` reads it: session_settings.h).
  void Resume() override { session_.adopt_effects = RecordedAdoptEffects(session_.procedure, session_.model); }

 protected:
  StepOutcome Run() override {
    PrepareCalibration();
    return session_.steps.Diagnosis();
  }

  void Answer(const Intent& intent, bool accept) override {
    const CalibrationOutcome* outcome = session_.steps.outcome();
    if (outcome == nullptr || !outcome->usable()) return;
    const std::vector<std::string> names = outcome->diagnosis.adopted_names();
    if (names.empty() && accept) return session_.sequence.FinishStep("none: the base model explains the data");
    if (names.empty()) return;
    if (accept) {
      session_.adopt_effects = true;
      return session_.sequence.FinishStep(fmt::format("adopted: {}", fmt::join(names, ", ")));
    }
    if (intent.kind == IntentKind::kAnswerNo) {
      session_.adopt_effects = false;
      return session_.sequence.FinishStep("declined: kept the base model");
    }
  }

  WizardScreen ResultScreen() const override { return WizardScreen::kDiagnosis; }

  void SetAnswerView(WizardView& v) const override {
    const CalibrationOutcome* outcome = session_.steps.outcome();
    if (outcome == nullptr || !outcome->usable()) return ResultStep::SetAnswerView(v);
    // In plain words (diagnosis_words.h), the recommended choice on Enter, the statistics on d.
    const GravitySpec& gravity = session_.gravity;
    const DiagnosisWords words = DiagnosisInPlainWords(outcome->diagnosis, gravity.gravity_mps2);
    const KeyHint details{"d", ShowingDetails() ? "plain words" : "statistics"};
    if (!words.asks) {
      v.prompt = words.prompt;
      v.keys = WithNavigation({{"Enter", "continue"}, details});
      return;
    }
    const bool ambiguous = !GravityAmbiguityNote(gravity, outcome->diagnosis.adopted_names()).empty();
    v.prompt = words.prompt + (ambiguous ? " Gravity is the standard value here, so a gravity error looks "
                                           "the same (see the gravity note): with it the report says "
                                           "INCOMPLETE."
                                         : "");
    v.keys = WithNavigation({{"Enter", words.recommended_action}, {"n", "keep basic model"}, details});
  }
};

}  // namespace

// session_settings.h: the outcome Answer records, read back (a resume, `accelcal refit`).
bool RecordedAdoptEffects(const Procedure& procedure, const SessionModel& model) {
  bool adopt = true;
  for (const ProcedureStep& step : procedure.steps)
    if (step.kind == StepKind::kDiagnosis)
      if (auto d = model.done_steps().find(step.id); d != model.done_steps().end())
        adopt = d->second.rfind("adopted", 0) == 0;
  return adopt;
}

StepControllerKind DiagnosisStepKind() {
  return {StepKind::kDiagnosis, &MakeStepController<DiagnosisStep>, &ResultEstimateS, nullptr, nullptr};
}

}  // namespace accelcal
