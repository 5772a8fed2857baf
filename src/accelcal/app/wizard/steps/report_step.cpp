// The report (kind "report"): the calibration of the model chosen recorded as the session's
// result with the session's gaps beside it (session_gaps.h), the report files written (through
// the wizard's outputs) and the verdict said first, with the next steps when it is not PASS;
// Enter finishes. It cannot be skipped. A required run the fit left out is offered to be taken
// again at once (Enter, recommended; n finishes INCOMPLETE); the session then comes back here
// and reports again. A session resumed after it shows the final summary again, computed from
// the journal (no file written), or, when a required run was left out, this step again with
// the same offer.
#include <set>

#include <fmt/core.h>

#include "accelcal/app/wizard/resume_summary.h"
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
      return;
    }
    recapped_ = !session_.steps.left_out_by_fit().empty();
  }

  // A required run the fit left out: the step is shown again to offer it.
  bool OpensAgainAtEnd() const override { return recapped_; }

 protected:
  StepOutcome Run() override {
    StepOutcome out;
    if (recapped_) {
      // Opened again at the end: the summary of the earlier run, nothing recorded again.
      recapped_ = false;
      out.lines = session_.steps.final_summary()->lines;
      out.details = session_.steps.final_summary()->details;
    } else {
      PrepareCalibration();
      out = session_.steps.Report(session_.adopt_effects, Meta(), CollectSessionGaps(session_.procedure, session_.model));
    }
    offer_.clear();
    for (const std::string& id : session_.steps.left_out_by_fit())
      if (offered_.count(id) == 0) {
        offer_ = id;
        break;
      }
    return out;
  }

  void Answer(const Intent& intent, bool accept) override {
    if (!session_.screen.problem.empty()) return;
    if (accept && !offer_.empty()) {
      offered_.insert(offer_);  // offered once a run: a run left out again is the technician's call
      return session_.sequence.RetakeStep(offer_);
    }
    if (accept || (intent.kind == IntentKind::kAnswerNo && !offer_.empty())) session_.sequence.FinishStep("written");
  }

  void Handle(const Intent& intent) override {
    // The report is not skipped, and r would write the same again.
    if (intent.kind == IntentKind::kRetry && session_.screen.problem.empty()) return;
    ResultStep::Handle(intent);
  }

  void SetAnswerView(WizardView& v) const override {
    if (offer_.empty()) {
      // A step after the report (a write-back into the vehicle) is still to come.
      const bool more = session_.sequence.SessionLeftS(true) > 0.0;
      v.prompt = more ? "Calibration recorded in the session; press Enter to go on."
                      : "Calibration recorded in the session; the verdict is above. Press Enter to finish.";
      v.keys = {{"Enter", more ? "go on" : "finish"}, {"d", ShowingDetails() ? "plain words" : "statistics"},
                {"b", "back"}, {"q", "save and quit"}};
      return;
    }
    const JournalCapture* left_out = session_.model.CaptureOf(offer_);
    for (const ProcedureStep& s : session_.procedure.steps)
      if (s.id == offer_)
        v.prompt = fmt::format(
            "The fit left out '{}' (capture {}): without it the session is INCOMPLETE. Enter takes "
            "it again now (recommended: mount it as asked; the other captures are kept); n finishes "
            "without it.",
            StepDisplayTitle(s), left_out != nullptr ? left_out->capture.id : 0);
    v.keys = {{"Enter", "take it again"}, {"n", "finish INCOMPLETE"},
              {"d", ShowingDetails() ? "plain words" : "statistics"}, {"b", "back"}, {"q", "save and quit"}};
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

  bool recapped_ = false;         // RecapAtEnd found a run to offer: Run shows its summary
  std::string offer_;             // the step whose run the fit left out, offered to be taken again
  std::set<std::string> offered_;  // the steps offered (and taken again) in this run
};

}  // namespace

StepControllerKind ReportStepKind() {
  return {StepKind::kReport, &MakeStepController<ReportStep>, &ResultEstimateS, nullptr, nullptr};
}

}  // namespace accelcal
