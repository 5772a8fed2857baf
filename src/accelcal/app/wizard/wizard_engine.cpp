// The wizard engine: construction, resume, the step flow and intents. Captures, records and the
// noise floor are in wizard_engine_capture.cpp; the welcome and the typed answers in
// wizard_engine_inputs.cpp; the view in wizard_engine_view.cpp.
#include "accelcal/app/wizard/wizard_engine.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>
#include <fmt/format.h>

#include "accelcal/base/error.h"
#include "accelcal/base/utc_time.h"
#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/app/wizard/resume_summary.h"
#include "accelcal/app/wizard/session_settings.h"
#include "accelcal/app/wizard/session_gaps.h"

namespace accelcal {
namespace {

bool IsCaptureStep(StepKind kind) {
  return kind == StepKind::kStatic || kind == StepKind::kRecord || kind == StepKind::kTurntable;
}

// The capture engine's stillness check as the procedure sets it.
StaticStabilityOptions StabilityOf(const Procedure& p) {
  StaticStabilityOptions o;
  o.std_multiplier = p.std_multiplier;
  o.trend_multiplier = p.trend_multiplier;
  return o;
}

}  // namespace

std::string WizardOptions::Validate() const {
  if (!(quiet_period_s > 0.0)) return "quiet_period_s must be positive";
  if (std::string why = gravity.Validate(); !why.empty()) return "gravity: " + why;
  return "";
}

WizardEngine::WizardEngine(Procedure procedure, SampleSource& source, SessionJournal& journal,
                           WizardOptions options)
    : procedure_(std::move(procedure)), source_(source), model_(journal),
      options_(std::move(options)),
      outputs_(options_.report_beside.empty() ? nullptr : MakeOutputsBesideSession(options_.report_beside)),
      steps_(procedure_, model_, options_.gravity, options_.session_name, outputs_.get()),
      gravity_(options_.gravity),
      clock_(model_, options_.wall_now_s),
      floor_guard_(procedure_.expected_noise_counts, procedure_.noise_floor_max_ratio, StabilityOf(procedure_)),
      acq_(options_.quiet_period_s) {
  if (std::string why = options_.Validate(); !why.empty()) throw Error("wizard options: " + why);
  if (procedure_.steps.empty()) throw Error("the procedure has no steps");
  ReadJournal();
}

WizardEngine::~WizardEngine() = default;

// ---- resume ---------------------------------------------------------------------------------

bool WizardEngine::StepRecorded(const std::string& id) const { return model_.StepRecorded(id); }

void WizardEngine::ReadJournal() {
  const std::vector<JournalCapture>& captures = model_.captures();
  const std::map<std::string, std::string>& done = model_.done_steps();
  for (const JournalCapture& c : captures) {
    next_capture_id_ = std::max(next_capture_id_, c.capture.id + 1);
    if (c.capture.kind == CaptureKind::kStatic && model_.LeftOutReason(c).empty() && !c.superseded())
      captured_.push_back({c.capture.id, c.capture.label, MeasuredUp(c.capture)});
  }
  // What the session recorded that its calibration depends on (session_settings.h): the
  // welcome's gravity and equipment, a lowered noise floor, a diagnosis decided in an earlier run.
  const SessionSettings settings = ReadSessionSettings(procedure_, model_);
  if (settings.gravity) gravity_ = *settings.gravity;
  steps_.set_equipment(settings.equipment);
  lowered_floor_ = settings.lowered_floor;
  adopt_effects_ = settings.adopt_effects;
  resumed_ = !captures.empty() || !done.empty() || !model_.inputs().empty();
  if (!resumed_) return;
  resume_lines_.push_back(fmt::format("Resuming session {}: {} captures and {} steps already recorded.",
                               options_.session_name, captures.size(), done.size()));
  resume_lines_.insert(resume_lines_.end(), options_.notes.begin(), options_.notes.end());
  // In the procedure's order, with the steps' titles (resume_summary.h).
  for (std::string& line : ResumeSummaryLines(procedure_, model_, kWelcomeStepId))
    resume_lines_.push_back(std::move(line));
  if (done.count(kWelcomeStepId) != 0) {
    resume_lines_.push_back("  gravity: " + gravity_.Describe());
    AdvanceFrom(0);
  } else {
    // The welcome was cut short: its answers so far are kept; ask the rest.
    while (welcome_field_ + 1 < WelcomeFields() && model_.inputs().count(kWelcomeStepId) != 0 &&
           model_.inputs().at(kWelcomeStepId).count(Welcome(welcome_field_).key) != 0)
      ++welcome_field_;
  }
}

Eigen::Vector3d WizardEngine::MeasuredUp(const Capture& c) const {
  return procedure_.nominal.Calibrate(c.stats().mean_counts).normalized();
}

// ---- step flow ------------------------------------------------------------------------------

void WizardEngine::AdvanceFrom(int index) {
  const int n = static_cast<int>(procedure_.steps.size());
  while (index < n && StepRecorded(procedure_.steps[static_cast<size_t>(index)].id)) ++index;
  EnterStep(index);
}

void WizardEngine::EnterStep(int index) {
  current_ = index;
  acq_.Stop();
  problem_.clear();
  hint_.clear();
  input_error_.clear();
  input_note_.clear();
  lines_.clear();
  details_.clear();
  show_details_ = false;
  if (current_ >= static_cast<int>(procedure_.steps.size())) {
    phase_ = Phase::kDone;
    if (!progressed_) RecapReport();  // resumed after the end: the summary, not a bare "complete"
    return;
  }
  const ProcedureStep& s = step();
  level_first_counts_.reset();
  switch (s.kind) {
    case StepKind::kTurntable:
      radius_m_ = s.radius_m;
      rpm_ = s.rpm;
      phase_ = Phase::kRadius;
      break;
    case StepKind::kFit: RunFit(); break;
    case StepKind::kDiagnosis: RunDiagnosis(); break;
    case StepKind::kReport: RunReport(); break;
    case StepKind::kAnalysis: RunAnalysis(); break;
    default: EnterPlace(); break;
  }
}

void WizardEngine::FinishStep(const std::string& outcome) {
  progressed_ = true;
  model_.RecordStepDone(step().id, outcome);
  AdvanceFrom(current_ + 1);
}

// s: asks first (a skipped required step keeps the report from PASS).
void WizardEngine::AskSkip() {
  if (Redoing()) return CancelRedo();  // s in a redo keeps the earlier capture
  const StepKind kind = step().kind;
  if (kind == StepKind::kFit || kind == StepKind::kReport) {
    problem_ = fmt::format("the {} cannot be skipped", StepKindToString(kind));
    return;
  }
  skip_from_ = phase_;
  acq_.Stop();
  if (source_.bench() != nullptr && kind == StepKind::kTurntable) source_.bench()->StopTurntable();
  phase_ = Phase::kConfirmSkip;
}

void WizardEngine::HandleConfirmSkip(const Intent& intent) {
  if (intent.kind == IntentKind::kSkip) return SkipStep();
  // Anything else keeps the step: back to its start (a running capture starts again).
  const Phase from = skip_from_;
  if (from == Phase::kRadius || from == Phase::kRpm || from == Phase::kResult) return EnterStep(current_);
  if (from == Phase::kLevelTurn || from == Phase::kLevelResult) return EnterStep(current_);
  EnterPlace();
}

void WizardEngine::SkipStep() {
  acq_.Stop();
  FinishStep("skipped");
}

// Back: within a step to its previous question; from a step's start to the nearest earlier
// capture step: a skipped one is entered, an accepted capture is offered to be taken again
// (wizard_engine_redo.cpp). A finished record is kept.
void WizardEngine::GoBack() {
  // b at the start of a redo keeps the capture it would have replaced.
  if (Redoing() && (phase_ == Phase::kPlace || phase_ == Phase::kQuietReady || phase_ == Phase::kRadius))
    return CancelRedo();
  if (phase_ == Phase::kRpm) {
    phase_ = Phase::kRadius;
    return;
  }
  if (phase_ == Phase::kCapture || phase_ == Phase::kRecord || phase_ == Phase::kProblem ||
      phase_ == Phase::kLevelTurn) {
    if (step().kind == StepKind::kTurntable) {
      phase_ = Phase::kRpm;
      acq_.Stop();
      return;
    }
    EnterPlace();
    return;
  }
  const std::map<std::string, std::string>& done = model_.done_steps();
  const int from = phase_ == Phase::kConfirmRedo ? redo_target_ : current_;
  for (int i = from - 1; i >= 0; --i) {
    const ProcedureStep& s = procedure_.steps[static_cast<size_t>(i)];
    if (RedoableCapture(s) != nullptr) return AskRedo(i);
    const bool has_capture = model_.CaptureOf(s.id) != nullptr;
    // A record that ran to its end is kept like an accepted capture.
    const auto d = done.find(s.id);
    const bool recorded = s.kind == StepKind::kRecord && d != done.end() && d->second != "skipped";
    if (IsCaptureStep(s.kind) && !has_capture && !recorded) {
      EnterStep(i);
      return;
    }
  }
  problem_ = "nothing to go back to: every earlier record is recorded and is kept";
}

void WizardEngine::Quit() {
  acq_.Stop();
  quit_ = true;
  phase_ = Phase::kDone;
}

// ---- fit, diagnosis, report -----------------------------------------------------------------

// The steps that compute (calibration_steps.h); the engine only shows what they say.
void WizardEngine::Show(StepOutcome outcome) {
  phase_ = Phase::kResult;
  lines_ = std::move(outcome.lines);
  details_ = std::move(outcome.details);
  show_details_ = false;
  problem_ = std::move(outcome.problem);
  hint_ = std::move(outcome.hint);
}

void WizardEngine::RunFit() {
  steps_.set_gravity(gravity_);
  steps_.set_noise_floor(floor_guard_.floor());
  Show(steps_.Fit());
}

void WizardEngine::RunDiagnosis() {
  steps_.set_gravity(gravity_);
  steps_.set_noise_floor(floor_guard_.floor());
  Show(steps_.Diagnosis());
}

ReportMeta WizardEngine::MetaForReport() const {
  ReportMeta meta;
  meta.session_path = options_.report_beside;
  meta.procedure = procedure_.title;
  meta.source = source_.Describe();
  meta.date_utc = UtcNowIso8601();
  return meta;
}

void WizardEngine::RunReport() {
  steps_.set_gravity(gravity_);
  steps_.set_noise_floor(floor_guard_.floor());
  Show(steps_.Report(adopt_effects_, MetaForReport(), CollectSessionGaps(procedure_, model_)));
}

void WizardEngine::RecapReport() {
  const bool reported = std::any_of(procedure_.steps.begin(), procedure_.steps.end(), [&](const ProcedureStep& s) {
    return s.kind == StepKind::kReport && StepRecorded(s.id);
  });
  if (!reported || steps_.final_summary() != nullptr) return;
  steps_.set_gravity(gravity_);
  steps_.set_noise_floor(floor_guard_.floor());
  try {
    steps_.Recap(adopt_effects_, MetaForReport(), CollectSessionGaps(procedure_, model_));
  } catch (const Error&) {
    // The summary is a convenience: the session and its reports stand without it.
  }
}

void WizardEngine::RunAnalysis() { Show(steps_.Analysis(step(), &analysis_outcome_)); }

// ---- polling --------------------------------------------------------------------------------

void WizardEngine::UpdateLive(const std::vector<Sample>& chunk) {
  if (chunk.empty()) return;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Sample& s : chunk) sum += s.raw_counts;
  live_counts_ = sum / static_cast<double>(chunk.size());
}

void WizardEngine::Poll(double timeout_s) {
  std::vector<Sample> chunk;
  source_.Read(timeout_s, &chunk);
  clock_.Shift(&chunk, model_);
  if (!clock_.note().empty() && !clock_noted_) {
    clock_noted_ = true;
    resume_lines_.push_back(clock_.note());
  }
  UpdateLive(chunk);
  // The capture's timeout on the wall clock too: a silent link sends no sample time (a record
  // has its silence limit).
  if (phase_ == Phase::kCapture || phase_ == Phase::kQuiet || phase_ == Phase::kRecord) {
    const AcquisitionEvent watched = acq_.Watch(SteadyNowS());
    if (watched != AcquisitionEvent::kNone) return OnAcquisition(watched);
  }
  if (chunk.empty()) {
    if (source_.status().link == LinkState::kEnded &&
        (phase_ == Phase::kCapture || phase_ == Phase::kQuiet || phase_ == Phase::kRecord)) {
      // Nothing more will come (a recording replayed to its end): say so instead of waiting.
      acq_.Stop();
      problem_ = "the source has ended: no more samples from " + source_.Describe();
      hint_ = "q leaves; everything accepted is in the session";
      phase_ = Phase::kProblem;
    }
    return;
  }
  if (phase_ == Phase::kQuiet || phase_ == Phase::kCapture || phase_ == Phase::kRecord)
    OnAcquisition(acq_.Feed(chunk, SteadyNowS()));
}

// ---- intents --------------------------------------------------------------------------------

void WizardEngine::Handle(const Intent& intent) {
  if (phase_ == Phase::kDone) return;
  notice_.clear();  // a confirmation stays until the next key
  if (intent.kind == IntentKind::kQuit) {
    Quit();
    return;
  }
  switch (phase_) {
    case Phase::kWelcome: HandleWelcome(intent); return;
    case Phase::kRadius:
    case Phase::kRpm: HandleTurntableInput(intent); return;
    case Phase::kResult: HandleResult(intent); return;
    case Phase::kConfirmSkip: HandleConfirmSkip(intent); return;
    case Phase::kConfirmRedo: HandleConfirmRedo(intent); return;
    default: HandleCaptureIntent(intent); return;
  }
}

void WizardEngine::HandleResult(const Intent& intent) {
  const StepKind kind = step().kind;
  if (intent.kind == IntentKind::kBack) return GoBack();
  if (intent.kind == IntentKind::kSkip) return AskSkip();
  if (intent.kind == IntentKind::kRetry) return EnterStep(current_);
  if (intent.kind == IntentKind::kDetails) {
    show_details_ = !show_details_ && !details_.empty();
    return;
  }
  const bool accept = intent.kind == IntentKind::kAccept || intent.kind == IntentKind::kSubmitText;
  const CalibrationOutcome* outcome = steps_.outcome();
  if (kind == StepKind::kFit) {
    if (accept && outcome != nullptr && outcome->usable())
      FinishStep("converged: " + outcome->diagnosis.base.BriefReport());
    return;
  }
  if (kind == StepKind::kDiagnosis) {
    if (outcome == nullptr || !outcome->usable()) return;
    const std::vector<std::string> names = outcome->diagnosis.adopted_names();
    if (names.empty() && accept) return FinishStep("none: the base model explains the data");
    if (names.empty()) return;
    if (accept) {
      adopt_effects_ = true;
      return FinishStep(fmt::format("adopted: {}", fmt::join(names, ", ")));
    }
    if (intent.kind == IntentKind::kAnswerNo) {
      adopt_effects_ = false;
      return FinishStep("declined: kept the base model");
    }
    return;
  }
  if (kind == StepKind::kReport && accept && problem_.empty()) FinishStep("written");
  if (kind == StepKind::kAnalysis && accept && problem_.empty()) FinishStep(analysis_outcome_);
}

}  // namespace accelcal
