// The wizard engine: construction, resume, the sequence of steps, polling and intents. The way
// back and the redo are in wizard_engine_redo.cpp, the view in wizard_engine_view.cpp; each
// step's own work is its controller's (steps/).
#include "accelcal/app/wizard/wizard_engine.h"

#include <algorithm>
#include <set>
#include <utility>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "accelcal/app/wizard/quantity_input.h"
#include "accelcal/app/wizard/refit_answer.h"
#include "accelcal/app/wizard/resume_summary.h"
#include "accelcal/app/wizard/session_gaps.h"
#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/app/wizard/time_estimate.h"
#include "accelcal/base/error.h"
#include "accelcal/base/utc_time.h"
#include "accelcal/session/sensor_journal_view.h"

namespace accelcal {

WizardEngine::WizardEngine(Procedure procedure, SampleSource& source, SessionJournal& journal,
                           WizardOptions options)
    : procedure_(std::move(procedure)), model_(journal), options_(std::move(options)),
      outputs_(options_.report_beside.empty() ? nullptr : MakeOutputsBesideSession(options_.report_beside)),
      session_(procedure_, source, model_, options_, outputs_.get(), *this), welcome_(session_) {
  if (std::string why = options_.Validate(); !why.empty()) throw Error("wizard options: " + why);
  if (procedure_.steps.empty()) throw Error("the procedure has no steps");
  for (const ProcedureStep& s : procedure_.steps) controllers_.push_back(ControllerKindOf(s.kind).make(s, session_));
  ReadJournal();
}

WizardEngine::~WizardEngine() = default;

StepController* WizardEngine::Current() {
  if (current_ < 0) return &welcome_;
  return InSteps(current_) ? controllers_[static_cast<size_t>(current_)].get() : nullptr;
}

const StepController* WizardEngine::Current() const {
  if (current_ < 0) return &welcome_;
  return InSteps(current_) ? controllers_[static_cast<size_t>(current_)].get() : nullptr;
}

// ---- resume ---------------------------------------------------------------------------------

namespace {

// Inputs of the session's own making: a session of several sensors records its lead and its
// plate's placement before the engine starts (sensor_journal_view.h), which no run answered.
bool HoldsAnswers(const SessionInputs& inputs) {
  for (const auto& [step, values] : inputs)
    if (step != kSensorSetStep && !values.empty()) return true;
  return false;
}

}  // namespace

void WizardEngine::ReadJournal() {
  const std::vector<JournalCapture>& captures = model_.captures();
  const std::map<std::string, std::string>& done = model_.done_steps();
  for (const JournalCapture& c : captures) {
    session_.next_capture_id = std::max(session_.next_capture_id, c.capture.id + 1);
    if (c.capture.kind == CaptureKind::kStatic && model_.LeftOutReason(c).empty() && !c.superseded())
      session_.captured.push_back({c.capture.id, c.capture.label, session_.MeasuredUp(c.capture)});
  }
  welcome_.Resume();
  session_.noise_floor.Resume();
  for (const std::unique_ptr<StepController>& c : controllers_) c->Resume();
  resumed_ = !captures.empty() || !done.empty() || HoldsAnswers(model_.inputs());
  if (!resumed_) return;
  resume_lines_.push_back(fmt::format("Resuming session {}: {} captures and {} steps already recorded.",
                                      options_.session_name, captures.size(), done.size()));
  // The command line's flags this run does not use, and what would (a refit).
  resume_lines_.insert(resume_lines_.end(), options_.notes.begin(), options_.notes.end());
  // In the procedure's order, with the steps' titles (resume_summary.h).
  for (std::string& line : ResumeSummaryLines(procedure_, model_, kWelcomeStepId))
    resume_lines_.push_back(std::move(line));
  if (done.count(kWelcomeStepId) != 0) {
    resume_lines_.push_back("  gravity: " + session_.gravity.Describe());
    for (std::string& line : welcome_.DeviceResumeLines()) resume_lines_.push_back(std::move(line));
    AdvanceFrom(0);
  }
}

// ---- the sequence ---------------------------------------------------------------------------

void WizardEngine::AdvanceFrom(int index) {
  const int n = static_cast<int>(procedure_.steps.size());
  while (index < n && model_.StepRecorded(procedure_.steps[static_cast<size_t>(index)].id)) ++index;
  EnterStep(index);
}

void WizardEngine::EnterStep(int index) {
  current_ = index;
  session_.acq.Stop();
  session_.screen.problem.clear();
  session_.screen.hint.clear();
  if (!InSteps(current_)) {
    flow_ = Flow::kDone;
    // Resumed after the end: the summary, not a bare "complete"; a step with something to offer
    // again (a run the fit left out) is entered instead.
    if (session_.progressed) return;
    for (const std::unique_ptr<StepController>& c : controllers_) c->RecapAtEnd();
    for (size_t i = 0; i < controllers_.size(); ++i)
      if (controllers_[i]->OpensAgainAtEnd()) {
        opened_again_ = true;
        return EnterStep(static_cast<int>(i));
      }
    // Finished with a calibration: its inputs may be corrected without a capture taken again.
    if (resumed_ && session_.steps.final_summary() != nullptr) flow_ = Flow::kOfferRefit;
    return;
  }
  flow_ = Flow::kStep;
  if (LeftOutByPlan()) {
    // Said after what the screen already said (the capture just accepted), every step of a run
    // of skips named.
    if (plan_skipped_.empty()) notice_before_skips_ = session_.screen.notice;
    plan_skipped_.push_back(fmt::format("'{}'", StepDisplayTitle(step())));
    const bool one = plan_skipped_.size() == 1;
    session_.screen.notice = fmt::format(
        "{}{}{} skipped: the capture plan leaves {} out, {} nothing for this sensor (b takes {} anyway)",
        notice_before_skips_, notice_before_skips_.empty() ? "" : "; ", fmt::join(plan_skipped_, ", "),
        one ? "it" : "them", one ? "it buys" : "they buy", one ? "it" : "them");
    return FinishStep("skipped");
  }
  plan_skipped_.clear();
  controllers_[static_cast<size_t>(current_)]->Enter();
}

// An optional step not yet taken that the capture plan leaves out (bench_plan.h: it buys nothing
// for this sensor) is skipped on the way forward; b goes back to it, and it is then taken.
bool WizardEngine::LeftOutByPlan() {
  const ProcedureStep& s = step();
  if (s.required || Redoing() || model_.StepRecorded(s.id)) return false;
  session_.bench_plan.Refresh(session_);
  return session_.bench_plan.LeavesOut(s);
}

// After a retake asked by a step (the report), back to that step even when it was recorded in an
// earlier run: it reports again with the run taken again.
void WizardEngine::ContinueFromFirstOpenStep() {
  const int back_to = std::exchange(retake_return_, -1);
  int index = 0;
  const int n = static_cast<int>(procedure_.steps.size());
  while (index < n && model_.StepRecorded(procedure_.steps[static_cast<size_t>(index)].id)) ++index;
  EnterStep(back_to >= 0 ? std::min(index, back_to) : index);
}

void WizardEngine::FinishStep(const std::string& outcome) {
  session_.progressed = true;
  model_.RecordStepDone(step().id, outcome);
  AdvanceFrom(current_ + 1);
}

// s: asks first (a skipped required step keeps the report from PASS).
void WizardEngine::AskSkip() {
  if (Redoing()) return CancelRedo();  // s in a redo keeps the earlier capture
  const StepKind kind = step().kind;
  if (!InfoOf(kind).skippable) {
    session_.screen.problem = fmt::format("the {} cannot be skipped", StepKindToString(kind));
    return;
  }
  Current()->Halt();
  flow_ = Flow::kConfirmSkip;
}

// s again skips; anything else keeps the step, which goes on from where it was.
void WizardEngine::HandleConfirmSkip(const Intent& intent) {
  if (intent.kind == IntentKind::kSkip) {
    session_.acq.Stop();
    return FinishStep("skipped");
  }
  flow_ = Flow::kStep;
  Current()->KeepAfterSkipDeclined();
}

void WizardEngine::Quit() {
  session_.acq.Stop();
  // Leaving a finished session's refit offer leaves it as it was: nothing to resume.
  quit_ = flow_ != Flow::kOfferRefit;
  flow_ = Flow::kDone;
}

// The answer to "Refit with new inputs?": Enter leaves the session as it is; corrections refit
// it (the earlier calibration kept), or are refused with why and asked again.
void WizardEngine::HandleOfferRefit(const Intent& intent) {
  if (intent.kind == IntentKind::kAccept || (intent.kind == IntentKind::kSubmitText && IsBlank(intent.text))) {
    flow_ = Flow::kDone;
    return;
  }
  if (intent.kind != IntentKind::kSubmitText) return;
  RefitAnswer answer = ParseRefitAnswer(intent.text);
  if (!answer.ok()) {
    refit_error_ = answer.error;
    return;
  }
  RefitRequest& request = answer.request;
  request.session_name = options_.session_name;
  request.report_beside = options_.report_beside;
  request.source = session_.source.Describe();
  request.now_utc = UtcNowIso8601();
  try {
    refit_ = RefitSession(model_, procedure_, request);
  } catch (const Error& e) {
    refit_error_ = e.what();
    return;
  }
  refit_error_.clear();
  flow_ = Flow::kDone;
}

// ---- polling --------------------------------------------------------------------------------

void WizardEngine::UpdateLive(const std::vector<Sample>& chunk) {
  if (chunk.empty()) return;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Sample& s : chunk) sum += s.raw_counts;
  session_.live_counts = sum / static_cast<double>(chunk.size());
}

void WizardEngine::Poll(double timeout_s) {
  SampleSource& source = session_.source;
  std::vector<Sample> chunk;
  source_notices_.Update(source.Read(timeout_s, &chunk), source.status());
  session_.clock.Shift(&chunk, model_);
  if (!session_.clock.note().empty() && !clock_noted_) {
    clock_noted_ = true;
    resume_lines_.push_back(session_.clock.note());
  }
  UpdateLive(chunk);
  StepController* on_screen = flow_ == Flow::kStep ? Current() : nullptr;
  const bool acquiring = on_screen != nullptr && on_screen->Acquiring();
  // The capture's timeout on the wall clock too: a silent link sends no sample time (a record
  // has its silence limit).
  if (acquiring) {
    const AcquisitionEvent watched = session_.acq.Watch(SteadyNowS());
    if (watched != AcquisitionEvent::kNone) return on_screen->OnAcquisition(watched);
  }
  if (chunk.empty()) {
    if (acquiring && source.status().link == LinkState::kEnded) {
      // Nothing more will come (a recording replayed to its end): say so instead of waiting.
      session_.acq.Stop();
      session_.screen.problem = "the source has ended: no more samples from " + source.Describe();
      session_.screen.hint = "q leaves; everything accepted is in the session";
      on_screen->OnSourceEnded();
    }
    return;
  }
  if (acquiring) on_screen->OnAcquisition(session_.acq.Feed(chunk, SteadyNowS()));
}

// ---- intents --------------------------------------------------------------------------------

void WizardEngine::Handle(const Intent& intent) {
  if (flow_ == Flow::kDone) return;
  session_.screen.notice.clear();  // a confirmation stays until the next key
  source_notices_.Acknowledge();   // so does what the source noticed
  if (intent.kind == IntentKind::kQuit) return Quit();
  switch (flow_) {
    case Flow::kStep: return Current()->Handle(intent);
    case Flow::kConfirmSkip: return HandleConfirmSkip(intent);
    case Flow::kConfirmRedo: return HandleConfirmRedo(intent);
    case Flow::kOfferRefit: return HandleOfferRefit(intent);
    case Flow::kDone: return;
  }
}

// The steps not yet recorded from the current one (or the next, once the current one runs).
double WizardEngine::SessionLeftS(bool current_started) const {
  const int first = current_started ? current_ + 1 : current_;
  // Each capture as the plan counts it (bench_plan.h), the steps it leaves out not at all; the
  // mounting of the run on the table is not paid again.
  std::set<std::string> mounted;
  if (InSteps(current_) && current_ < first && InfoOf(step().kind).acquires == StepAcquires::kTurntableCapture)
    (void)session_.bench_plan.StepLeftS(step(), 0.0, &mounted);
  double total_s = 0.0;
  for (int i = std::max(first, 0); InSteps(i); ++i) {
    const ProcedureStep& s = procedure_.steps[static_cast<size_t>(i)];
    if (!model_.StepRecorded(s.id)) total_s += session_.bench_plan.StepLeftS(s, StepEstimateS(s), &mounted);
  }
  return total_s;
}

}  // namespace accelcal
