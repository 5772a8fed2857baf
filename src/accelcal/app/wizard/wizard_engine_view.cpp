// The wizard engine's view-model: what a front end draws. The session's parts (the resume
// summary, the noise floor, the source, the time, the redo) are the engine's; the step's screen
// is its controller's.
#include <algorithm>

#include <fmt/core.h>

#include "accelcal/app/wizard/resume_summary.h"
#include "accelcal/app/wizard/time_estimate.h"
#include "accelcal/app/wizard/wizard_engine.h"

namespace accelcal {

WizardView WizardEngine::View() const {
  const StepController* c = Current();
  WizardView v;
  v.session = options_.session_name;
  v.procedure = procedure_.title;
  v.resumed = resumed_;
  v.step_count = static_cast<int>(procedure_.steps.size()) + 1;
  v.step_index = std::min(current_ + 2, v.step_count);
  v.live_counts = session_.live_counts;
  if (session_.live_counts.allFinite())
    v.live_g = procedure_.nominal.Calibrate(session_.live_counts).norm() / session_.gravity.gravity_mps2;
  v.problem = session_.screen.problem;
  v.hint = session_.screen.hint;
  // The resume summary is shown until this run has recorded something of its own; a finished
  // session's step opened again says only the flags this run does not use before its own text.
  if (resumed_ && !session_.progressed) v.lines = opened_again_ ? options_.notes : resume_lines_;
  if (c != nullptr) c->AddText(v.lines);
  // What the noise floor's checks said, beside the steps that acquire.
  const bool result_shown = flow_ == Flow::kStep && c != nullptr && c->ShowsResult();
  if (!result_shown && flow_ != Flow::kDone) {
    const std::vector<std::string>& floor_lines = session_.noise_floor.lines();
    v.lines.insert(v.lines.end(), floor_lines.begin(), floor_lines.end());
  }
  v.noise_floor_text = session_.noise_floor.Describe();
  v.status = session_.source.Describe() + ": " + session_.source.status().BriefReport();
  v.source_notice = source_notices_.text();
  v.source_detail = source_notices_.detail();
  SetStepView(v);
  SetFlowView(v);
  SetTimeView(v);
  v.notice = session_.screen.notice;
  AddRedoLines(v);
  if (InSteps(current_)) c->AddLive(v, flow_ == Flow::kStep);
  if (session_.source.status().link == LinkState::kDead && v.problem.empty()) {
    v.problem = "no samples: " + session_.source.status().link_error;
    v.hint = "check the cable or the sample server; the wizard goes on when samples return";
  }
  return v;
}

void WizardEngine::SetStepView(WizardView& v) const {
  if (const StepController* c = Current()) return c->SetHeader(v);
  v.step_title = "Done";
}

void WizardEngine::SetFlowView(WizardView& v) const {
  switch (flow_) {
    case Flow::kStep: return Current()->SetView(v);
    case Flow::kConfirmSkip: return SetConfirmSkipView(v);
    case Flow::kConfirmRedo: return SetConfirmRedoView(v);
    case Flow::kOfferRefit: return SetOfferRefitView(v);
    case Flow::kDone: return SetDoneView(v);
  }
}

// The refit this run made: what changed, the new verdict and numbers, the earlier result kept.
void WizardEngine::SetRefittedView(WizardView& v) const {
  const FinalSummary& summary = refit_->summary;
  v.verdict = std::string(VerdictToString(summary.verdict));
  v.prompt = summary.ending;
  v.lines = {fmt::format("Refitted ({}), the captures fitted again with:", refit_->refit_step)};
  if (refit_->changes.empty()) v.lines.push_back("  no input changed: fitted again as recorded");
  for (const std::string& change : refit_->changes) v.lines.push_back("  " + change);
  v.lines.insert(v.lines.end(), summary.lines.begin(), summary.lines.end());
  v.lines.push_back(fmt::format("The earlier calibration{} kept in the session; `accelcal report {}` shows "
                                "this one and lists what changed.",
                                refit_->earlier_results == 1 ? " is" : "s are", options_.session_name));
}

// A finished session opened again: its verdict and numbers, and the offer to correct its inputs.
void WizardEngine::SetOfferRefitView(WizardView& v) const {
  const FinalSummary& summary = *session_.steps.final_summary();
  v.screen = WizardScreen::kDone;
  v.verdict = std::string(VerdictToString(summary.verdict));
  v.prompt = fmt::format("This session is finished: {} in an earlier run. A wrong gravity, equipment or "
                         "identification is corrected by fitting its captures again (the earlier calibration "
                         "is kept). Refit it with new inputs?",
                         v.verdict);
  v.lines = options_.notes;
  v.lines.insert(v.lines.end(), summary.lines.begin(), summary.lines.end());
  v.input = InputRequest{"refit",
                         "What changed (gravity 9.78030 +- 0.00002 or gravity lat -34.9 alt 43; equipment "
                         "ruler id RUL-07 cal C-2291; device SN; operator NAME; place TEXT), or Enter to "
                         "leave it as it is",
                         "", refit_error_};
  v.keys = {{"Enter", "leave it as it is"}, {"q", "leave"}};
}

void WizardEngine::SetConfirmSkipView(WizardView& v) const {
  v.screen = WizardScreen::kPlacePose;
  v.prompt = step().required
                 ? fmt::format("Skip '{}'? The procedure requires it: without it the report's verdict "
                               "is INCOMPLETE. Press s again to skip it, Enter to do it.", StepDisplayTitle(step()))
                 : fmt::format("Skip '{}'? The report will list it as skipped. Press s again to skip "
                               "it, Enter to do it.", StepDisplayTitle(step()));
  v.keys = {{"s", "skip it"}, {"Enter", "do it"}, {"q", "save and quit"}};
}

void WizardEngine::SetDoneView(WizardView& v) const {
  v.screen = WizardScreen::kDone;
  v.finished = true;
  const bool calibrates = std::any_of(procedure_.steps.begin(), procedure_.steps.end(),
                                      [](const ProcedureStep& s) { return InfoOf(s.kind).calibrates; });
  if (quit_) {
    v.prompt = fmt::format("Saved. Everything accepted is in session {}; run the wizard on it again "
                           "to resume.", options_.session_name);
    return;
  }
  v.prompt = calibrates ? "Calibration complete." : "Procedure complete: every step is recorded.";
  // The verdict and the headline numbers of this run's report (final_summary.h).
  if (const FinalSummary* summary = session_.steps.final_summary()) {
    v.verdict = std::string(VerdictToString(summary->verdict));
    // The verdict is the summary's first line; the prompt says what it means ("Calibration
    // complete." only for a PASS) and where the next steps are.
    v.prompt = resumed_ && !session_.progressed ? EarlierEnding(summary->verdict) : summary->ending;
    if (refit_) return SetRefittedView(v);
    v.lines = summary->lines;
    // The flags this run did not use, and what would (a refit), before the summary.
    if (resumed_ && !session_.progressed) v.lines.insert(v.lines.begin(), options_.notes.begin(), options_.notes.end());
  }
}

// Every screen but the final one says the time; a running capture or record has set its own
// (it knows its progress).
void WizardEngine::SetTimeView(WizardView& v) const {
  if (flow_ == Flow::kDone || flow_ == Flow::kOfferRefit || !v.time_text.empty()) return;
  v.session_left_s = SessionLeftS(false);
  if (!InSteps(current_)) {
    v.time_text = WaitingTimeText(kNaN, kNaN, v.session_left_s);
    return;
  }
  // The last step's result on screen (the report): nothing is left to wait for, so no time is
  // left either (its reading allowance is the technician's, not the session's).
  if (flow_ == Flow::kStep && Current()->ShowsResult() && SessionLeftS(true) == 0.0) {
    v.session_left_s = 0.0;
    v.time_text = LastStepTimeText();
    return;
  }
  v.time_text = WaitingTimeText(Current()->WaitingCaptureS(flow_ == Flow::kStep), step().timeout_s, v.session_left_s);
}

}  // namespace accelcal
