// The fit (kind "fit"): the nine-parameter fit of the accepted captures (the pipeline's base
// stage); Enter goes on once it converged. It cannot be skipped (the step-kind table says so).
#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/app/wizard/steps/result_step.h"

namespace accelcal {
namespace {

class FitStep final : public ResultStep {
 public:
  using ResultStep::ResultStep;

 protected:
  StepOutcome Run() override {
    PrepareCalibration();
    return session_.steps.Fit();
  }

  void Answer(const Intent&, bool accept) override {
    const CalibrationOutcome* outcome = session_.steps.outcome();
    if (accept && outcome != nullptr && outcome->usable())
      session_.sequence.FinishStep("converged: " + outcome->diagnosis.base.BriefReport());
  }

  WizardScreen ResultScreen() const override { return WizardScreen::kFit; }
};

}  // namespace

StepControllerKind FitStepKind() {
  return {StepKind::kFit, &MakeStepController<FitStep>, &ResultEstimateS, nullptr, nullptr};
}

}  // namespace accelcal
