// The report (kind "report"): the calibration of the model chosen recorded as the session's
// result with the session's gaps beside it (session_gaps.h), the report files written (through
// the wizard's outputs) and the verdict said; Enter finishes. It cannot be skipped. A session
// resumed after it shows the final summary again, computed from the journal (no file written).
#include "accelcal/app/wizard/session_gaps.h"
#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/app/wizard/steps/result_step.h"
#include "accelcal/base/error.h"
#include "accelcal/base/utc_time.h"

namespace accelcal {
namespace {

class ReportStep final : public ResultStep {
 public:
  using ResultStep::ResultStep;

  // A session resumed after its report step: the final summary computed again (no file written).
  void RecapAtEnd() override {
    if (!session_.model.StepRecorded(step_.id) || session_.steps.final_summary() != nullptr) return;
    PrepareCalibration();
    try {
      session_.steps.Recap(session_.adopt_effects, Meta(), CollectSessionGaps(session_.procedure, session_.model));
    } catch (const Error&) {
      // The summary is a convenience: the session and its reports stand without it.
    }
  }

 protected:
  StepOutcome Run() override {
    PrepareCalibration();
    return session_.steps.Report(session_.adopt_effects, Meta(),
                                 CollectSessionGaps(session_.procedure, session_.model));
  }

  void Answer(const Intent&, bool accept) override {
    if (accept && session_.screen.problem.empty()) session_.sequence.FinishStep("written");
  }

  void SetAnswerView(WizardView& v) const override {
    ResultStep::SetAnswerView(v);
    // A step after the report (a write-back into the vehicle) is still to come.
    const bool more = session_.sequence.SessionLeftS(true) > 0.0;
    v.prompt = more ? "Calibration recorded in the session; press Enter to go on."
                    : "Calibration recorded in the session; press Enter to finish.";
  }

 private:
  ReportMeta Meta() const {
    ReportMeta meta;
    meta.session_path = session_.options.report_beside;
    meta.procedure = session_.procedure.title;
    meta.source = session_.source.Describe();
    meta.date_utc = UtcNowIso8601();
    return meta;
  }
};

}  // namespace

StepControllerKind ReportStepKind() {
  return {StepKind::kReport, &MakeStepController<ReportStep>, &ResultEstimateS, nullptr, nullptr};
}

}  // namespace accelcal
