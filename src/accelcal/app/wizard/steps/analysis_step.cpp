// The analysis of an earlier record (kind "analysis"): its noise (standard deviation, noise
// density, normality) or its Allan deviation and drift, shown; its figures in one line are the
// step's outcome in the journal.
#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/app/wizard/steps/result_step.h"

namespace accelcal {
namespace {

class AnalysisStep final : public ResultStep {
 public:
  using ResultStep::ResultStep;

 protected:
  StepOutcome Run() override { return session_.steps.Analysis(step_, &outcome_); }

  void Answer(const Intent&, bool accept) override {
    if (accept && session_.screen.problem.empty()) session_.sequence.FinishStep(outcome_);
  }

 private:
  std::string outcome_;  // the analysis's figures, for the journal
};

}  // namespace

StepControllerKind AnalysisStepKind() {
  return {StepKind::kAnalysis, &MakeStepController<AnalysisStep>, &ResultEstimateS, nullptr, nullptr};
}

}  // namespace accelcal
