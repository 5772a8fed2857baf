#include "accelcal/app/wizard/steps/result_step.h"

#include "accelcal/app/wizard/time_estimate.h"

namespace accelcal {

// The steps that compute (calibration_steps.h); the step only shows what they say.
void ResultStep::Enter() {
  StepOutcome outcome = Run();
  lines_ = std::move(outcome.lines);
  details_ = std::move(outcome.details);
  show_details_ = false;
  dead_end_ = !outcome.problem.empty();
  session_.screen.problem = std::move(outcome.problem);
  session_.screen.hint = std::move(outcome.hint);
}

void ResultStep::PrepareCalibration() {
  session_.steps.set_gravity(session_.gravity);
  session_.steps.set_noise_floor(session_.noise_floor.floor());
}

void ResultStep::Handle(const Intent& intent) {
  if (intent.kind == IntentKind::kBack) return session_.sequence.GoBack();
  if (intent.kind == IntentKind::kSkip) return session_.sequence.AskSkip();
  if (intent.kind == IntentKind::kRetry) return session_.sequence.RestartStep();
  if (intent.kind == IntentKind::kDetails) {
    show_details_ = !show_details_ && !details_.empty();
    return;
  }
  const bool accept = intent.kind == IntentKind::kAccept || intent.kind == IntentKind::kSubmitText;
  // A dead end (a refused fit): Enter saves and leaves, with the problem on the last screen. It
  // did nothing before, and a person (or a script) answering Enter there went round forever.
  if (accept && dead_end_) return session_.sequence.SaveAndLeave();
  Answer(intent, accept);
}

void ResultStep::SetHeader(WizardView& v) const {
  v.step_title = step_.title;
  v.pose_name = step_.pose_name;
}

void ResultStep::AddText(std::vector<std::string>& lines) const {
  const std::vector<std::string>& text = show_details_ ? details_ : lines_;
  lines.insert(lines.end(), text.begin(), text.end());
}

void ResultStep::SetView(WizardView& v) const {
  v.screen = ResultScreen();
  if (dead_end_) {
    v.prompt = "The session cannot go on from here as it is: Enter saves and quits (it resumes here).";
    v.keys = WithNavigation({{"Enter", "save and quit"}, {"r", "retry"}});
    return;
  }
  SetAnswerView(v);
}

void ResultStep::SetAnswerView(WizardView& v) const {
  v.prompt = "Press Enter to continue.";
  v.keys = {{"Enter", "continue"}, {"r", "retry"}};
  if (!details_.empty()) v.keys.push_back({"d", show_details_ ? "plain words" : "statistics"});
  v.keys = WithNavigation(v.keys);
}

double ResultEstimateS(const ProcedureStep&, const TimeAllowances& a) { return a.read_result_s; }

}  // namespace accelcal
