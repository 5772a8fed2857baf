// What the steps that compute rather than capture (fit, diagnosis, report, analysis) share: each
// runs when it is entered (calibration_steps.h: the one pipeline over the session), shows what it
// has to say (the statistics behind it on d), and goes on with Enter; r runs it again. A step
// that cannot go on says so and offers r; Enter there saves and quits (never a dead loop).
#pragma once

#include <string>
#include <vector>

#include "accelcal/app/wizard/step_controller.h"
#include "accelcal/app/wizard/time_estimate.h"
#include "accelcal/app/wizard/wizard_session.h"
#include "accelcal/session/procedure.h"

namespace accelcal {

class ResultStep : public StepController {
 public:
  // Borrows both: they outlive the controller.
  ResultStep(const ProcedureStep& step, WizardSession& session) : step_(step), session_(session) {}

  void Enter() override;
  void Handle(const Intent& intent) override;
  void KeepAfterSkipDeclined() override { session_.sequence.RestartStep(); }
  void SetHeader(WizardView& v) const override;
  void AddText(std::vector<std::string>& lines) const override;
  bool ShowsResult() const override { return true; }
  void SetView(WizardView& v) const override;

 protected:
  // Computes the step's outcome (the step is entered).
  virtual StepOutcome Run() = 0;
  // Enter (`accept`) or n: the step finishes when its outcome allows it.
  virtual void Answer(const Intent& intent, bool accept) = 0;
  virtual WizardScreen ResultScreen() const { return WizardScreen::kReport; }
  // The prompt and keys under the result when it can go on.
  virtual void SetAnswerView(WizardView& v) const;
  // The session's gravity and noise floor handed to the calibration steps before they run.
  void PrepareCalibration();
  // d shows the statistics behind the result.
  bool ShowingDetails() const { return show_details_; }

  const ProcedureStep& step_;
  WizardSession& session_;

 private:
  std::vector<std::string> lines_;
  std::vector<std::string> details_;  // the statistics behind lines_ (d shows them)
  bool show_details_ = false;
  bool dead_end_ = false;  // the outcome is a problem: the step cannot go on (Enter saves and quits)
};

// The handling allowance of a step that shows a result, s.
double ResultEstimateS(const ProcedureStep& step, const TimeAllowances& allowances);

}  // namespace accelcal
