// The wizard engine's redo: b at a step's start reaches an accepted capture of an earlier static
// or turntable step and offers to take it again. The old capture is replaced only when the new
// one is accepted (SessionJournal::RecordRedoCapture: the new one recorded and the old one
// marked superseded in one transaction); until then b, s or q keep it.
#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/app/wizard/wizard_engine.h"

namespace accelcal {

const JournalCapture* WizardEngine::RedoableCapture(const ProcedureStep& s) const {
  if (s.kind != StepKind::kStatic && s.kind != StepKind::kTurntable) return nullptr;
  return model_.CaptureOf(s.id);
}

void WizardEngine::AskRedo(int step_index) {
  if (phase_ != Phase::kConfirmRedo) redo_from_phase_ = phase_;
  redo_target_ = step_index;
  problem_.clear();
  hint_.clear();
  phase_ = Phase::kConfirmRedo;
}

void WizardEngine::HandleConfirmRedo(const Intent& intent) {
  if (intent.kind == IntentKind::kAccept || intent.kind == IntentKind::kSubmitText) return StartRedo();
  if (intent.kind == IntentKind::kBack) return GoBack();  // further back from the step offered
  // n (or anything else) keeps the capture: back where b was pressed.
  problem_.clear();
  phase_ = redo_from_phase_;
}

void WizardEngine::StartRedo() {
  const ProcedureStep& target = procedure_.steps[static_cast<size_t>(redo_target_)];
  const JournalCapture* old = RedoableCapture(target);
  if (old == nullptr) {  // cannot happen: the offer was made for it
    phase_ = redo_from_phase_;
    return;
  }
  const std::string old_step_id = old->step_id;
  const int old_id = old->capture.id;
  const double old_radius_m = old->capture.radius_m;
  const double old_rpm = old->capture.rpm;
  EnterStep(redo_target_);
  redo_of_ = old_step_id;
  redo_capture_id_ = old_id;
  redo_note_.clear();
  // A turntable run taken again offers the radius and speed it was taken with.
  if (target.kind == StepKind::kTurntable && std::isfinite(old_radius_m) && std::isfinite(old_rpm)) {
    radius_m_ = old_radius_m;
    rpm_ = old_rpm;
  }
}

void WizardEngine::CancelRedo() {
  const std::string title = step().title;
  const int kept = redo_capture_id_;
  redo_of_.clear();
  acq_.Stop();
  if (step().kind == StepKind::kTurntable && source_.bench() != nullptr) source_.bench()->StopTurntable();
  AdvanceFrom(0);
  redo_note_ = fmt::format("Kept the earlier capture {} of '{}': nothing was replaced.", kept, title);
  redo_note_captures_ = model_.captures().size();
}

void WizardEngine::RecordAcceptedCapture(const Capture& capture) {
  const std::string journal_id = model_.NextCaptureStepId(step().id);
  if (!Redoing()) {
    model_.RecordCapture(journal_id, capture);
    return;
  }
  model_.RecordRedoCapture(journal_id, capture, redo_of_);
  const int old_id = redo_capture_id_;
  std::erase_if(captured_, [&](const CapturedPose& p) { return p.capture_id == old_id; });
  redo_of_.clear();
  redo_note_ = fmt::format("'{}' taken again: capture {} replaces capture {} (kept in the session, "
                           "marked superseded, out of the fit and the report).",
                           step().title, capture.id, old_id);
  redo_note_captures_ = model_.captures().size();
}

void WizardEngine::SetConfirmRedoView(WizardView& v) const {
  const ProcedureStep& target = procedure_.steps[static_cast<size_t>(redo_target_)];
  const JournalCapture* old = RedoableCapture(target);
  v.step_index = redo_target_ + 2;
  v.step_title = target.title;
  v.pose_name = target.pose_name;
  v.expected_up = target.kind == StepKind::kTurntable ? SensorAxisVector(target.up_axis) : target.up;
  v.screen = target.kind == StepKind::kTurntable ? WizardScreen::kMountTurntable : WizardScreen::kPlacePose;
  v.prompt = fmt::format(
      "Take '{}' again? Its capture {} was accepted. The new capture replaces it once accepted; the "
      "old one stays in the session, marked superseded, out of the fit and the report. Enter takes "
      "it again, b looks further back, n keeps it.",
      target.title, old != nullptr ? old->capture.id : 0);
  v.keys = {{"Enter", "take it again"}, {"b", "further back"}, {"n", "keep it"}, {"q", "save and quit"}};
}

void WizardEngine::AddRedoLines(WizardView& v) const {
  if (Redoing() && phase_ != Phase::kDone) {
    v.lines.push_back(fmt::format("Taking '{}' again: capture {} stays until this one is accepted "
                                  "(b or s keeps it).", step().title, redo_capture_id_));
    return;
  }
  // The outcome of the last redo, until the next capture.
  if (!redo_note_.empty() && redo_note_captures_ == model_.captures().size() &&
      phase_ != Phase::kConfirmRedo && phase_ != Phase::kDone)
    v.lines.push_back(redo_note_);
}

}  // namespace accelcal
