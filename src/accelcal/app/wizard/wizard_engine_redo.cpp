// The wizard engine's way back and redo: b, when the step goes no further back within itself,
// reaches the nearest earlier step that keeps a capture or a record (the step-kind table's
// KeepsData): one without is entered; an accepted static or turntable capture is offered to be
// taken again. The old capture is replaced only when the new one is accepted
// (SessionJournal::RecordRedoCapture: the new one recorded and the old one marked superseded in
// one transaction); until then b, s or q keep it.
#include <algorithm>

#include <fmt/core.h>

#include "accelcal/app/wizard/resume_summary.h"
#include "accelcal/app/wizard/wizard_engine.h"

namespace accelcal {

// Back: within a step to its previous question; from a step's start to the nearest earlier
// capture step. A finished record is kept.
void WizardEngine::GoBack() {
  if (flow_ == Flow::kStep) {
    StepController* c = Current();
    // b at the start of a redo keeps the capture it would have replaced.
    if (Redoing() && c->AtStart()) return CancelRedo();
    if (c->BackWithin()) return;
  }
  const std::map<std::string, std::string>& done = model_.done_steps();
  const int from = flow_ == Flow::kConfirmRedo ? redo_target_ : current_;
  for (int i = from - 1; i >= 0; --i) {
    const ProcedureStep& s = procedure_.steps[static_cast<size_t>(i)];
    if (RedoableCapture(s) != nullptr) return AskRedo(i);
    const bool has_capture = model_.CaptureOf(s.id) != nullptr;
    // A record that ran to its end is kept like an accepted capture.
    const auto d = done.find(s.id);
    const bool kept = IsRecordStep(s.kind) && d != done.end() && d->second != "skipped";
    if (KeepsData(s.kind) && !has_capture && !kept) return EnterStep(i);
  }
  session_.screen.problem = "nothing to go back to: every earlier record is recorded and is kept";
}

void WizardEngine::RetakeStep(const std::string& step_id) {
  for (size_t i = 0; i < procedure_.steps.size(); ++i) {
    if (procedure_.steps[i].id != step_id || RedoableCapture(procedure_.steps[i]) == nullptr) continue;
    redo_target_ = static_cast<int>(i);
    retake_return_ = current_;
    return StartRedo();
  }
}

const JournalCapture* WizardEngine::RedoableCapture(const ProcedureStep& s) const {
  return KeepsCapture(s.kind) ? model_.CaptureOf(s.id) : nullptr;
}

void WizardEngine::AskRedo(int step_index) {
  redo_target_ = step_index;
  session_.screen.problem.clear();
  session_.screen.hint.clear();
  flow_ = Flow::kConfirmRedo;
}

void WizardEngine::HandleConfirmRedo(const Intent& intent) {
  if (intent.kind == IntentKind::kAccept || intent.kind == IntentKind::kSubmitText) return StartRedo();
  if (intent.kind == IntentKind::kBack) return GoBack();  // further back from the step offered
  // n (or anything else) keeps the capture: back where b was pressed.
  session_.screen.problem.clear();
  flow_ = Flow::kStep;
}

void WizardEngine::StartRedo() {
  const ProcedureStep& target = procedure_.steps[static_cast<size_t>(redo_target_)];
  const JournalCapture* old = RedoableCapture(target);
  if (old == nullptr) {  // cannot happen: the offer was made for it
    flow_ = Flow::kStep;
    return;
  }
  const std::string old_step_id = old->step_id;
  const int old_id = old->capture.id;
  EnterStep(redo_target_);
  redo_of_ = old_step_id;
  redo_capture_id_ = old_id;
  redo_note_.clear();
  // The step starts again as the old capture was taken (a turntable run: its radius and speed).
  if (const JournalCapture* again = RedoableCapture(target)) Current()->BeginRedo(again->capture);
}

void WizardEngine::CancelRedo() {
  const std::string title = StepDisplayTitle(step());
  const int kept = redo_capture_id_;
  redo_of_.clear();
  Current()->Halt();
  ContinueFromFirstOpenStep();
  redo_note_ = fmt::format("Kept the earlier capture {} of '{}': nothing was replaced.", kept, title);
  redo_note_captures_ = model_.captures().size();
}

void WizardEngine::RecordCapture(const Capture& capture) {
  session_.progressed = true;
  const std::string journal_id = model_.NextCaptureStepId(step().id);
  if (!Redoing()) {
    model_.RecordCapture(journal_id, capture);
    return;
  }
  model_.RecordRedoCapture(journal_id, capture, redo_of_);
  const int old_id = redo_capture_id_;
  std::erase_if(session_.captured, [&](const CapturedPose& p) { return p.capture_id == old_id; });
  redo_of_.clear();
  redo_note_ = fmt::format("'{}' taken again: capture {} replaces capture {} (kept in the session, "
                           "marked superseded, out of the fit and the report).",
                           StepDisplayTitle(step()), capture.id, old_id);
  redo_note_captures_ = model_.captures().size();
}

void WizardEngine::SetConfirmRedoView(WizardView& v) const {
  const ProcedureStep& target = procedure_.steps[static_cast<size_t>(redo_target_)];
  const StepController& asked = *controllers_[static_cast<size_t>(redo_target_)];
  const JournalCapture* old = RedoableCapture(target);
  v.step_index = redo_target_ + 2;
  asked.SetHeader(v);
  v.screen = asked.PlaceScreen();
  v.prompt = fmt::format(
      "Take '{}' again? Its capture {} was accepted. The new capture replaces it once accepted; the "
      "old one stays in the session, marked superseded, out of the fit and the report. Enter takes "
      "it again, b looks further back, n keeps it.",
      StepDisplayTitle(target), old != nullptr ? old->capture.id : 0);
  v.keys = {{"Enter", "take it again"}, {"b", "further back"}, {"n", "keep it"}, {"q", "save and quit"}};
}

void WizardEngine::AddRedoLines(WizardView& v) const {
  if (Redoing() && flow_ != Flow::kDone) {
    v.lines.push_back(fmt::format("Taking '{}' again: capture {} stays until this one is accepted "
                                  "(b or s keeps it).", StepDisplayTitle(step()), redo_capture_id_));
    return;
  }
  // The outcome of the last redo, until the next capture.
  if (!redo_note_.empty() && redo_note_captures_ == model_.captures().size() && flow_ != Flow::kConfirmRedo &&
      flow_ != Flow::kDone)
    v.lines.push_back(redo_note_);
}

}  // namespace accelcal
