#include "accelcal/app/wizard/wizard_engine.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/core.h>
#include <fmt/format.h>

#include "accelcal/base/error.h"
#include "accelcal/base/utc_time.h"
#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/app/wizard/leveling.h"
#include "accelcal/app/wizard/quantity_input.h"

namespace accelcal {
namespace {

constexpr const char* kWelcomeId = "welcome";

bool IsCaptureStep(StepKind kind) {
  return kind == StepKind::kStatic || kind == StepKind::kRecord || kind == StepKind::kTurntable;
}

bool NeedsSensor(StepKind kind) { return IsCaptureStep(kind) || kind == StepKind::kLevel; }

// Measured "up" of a capture through the rough model (platform frame, unit).
Eigen::Vector3d MeasuredUp(const Capture& c, const SensorModel& rough) {
  return rough.Calibrate(c.stats().mean_counts).normalized();
}

}  // namespace

std::string WizardOptions::Validate() const {
  if (!(quiet_period_s > 0.0)) return "quiet_period_s must be positive";
  if (!(gravity.gravity_mps2 > 0.0)) return "gravity must be positive";
  return "";
}

WizardEngine::WizardEngine(Procedure procedure, SampleSource& source, SessionJournal& journal,
                           WizardOptions options)
    : procedure_(std::move(procedure)), source_(source), model_(journal),
      options_(std::move(options)),
      outputs_(options_.report_beside.empty() ? nullptr : MakeOutputsBesideSession(options_.report_beside)),
      steps_(procedure_, model_, options_.gravity, options_.session_name, outputs_.get()),
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
    if (c.capture.kind == CaptureKind::kStatic)
      captured_.push_back({c.capture.id, c.capture.label, MeasuredUp(c.capture, procedure_.nominal)});
  }
  // A diagnosis decided in an earlier run: adopted effects go into the report.
  for (const ProcedureStep& s : procedure_.steps)
    if (s.kind == StepKind::kDiagnosis)
      if (auto d = done.find(s.id); d != done.end()) adopt_effects_ = d->second.rfind("adopted", 0) == 0;
  resumed_ = !captures.empty() || !done.empty() || !model_.inputs().empty();
  if (!resumed_) return;
  resume_lines_.push_back(fmt::format("Resuming session {}: {} captures and {} steps already recorded.",
                               options_.session_name, captures.size(), done.size()));
  for (const JournalCapture& c : captures)
    resume_lines_.push_back(fmt::format("  done: {} (capture {}, {})", c.step_id, c.capture.id, c.capture.label));
  for (const auto& [id, outcome] : done) resume_lines_.push_back(fmt::format("  done: {} ({})", id, outcome));
  for (const std::string& id : model_.RecordSteps()) {
    if (done.count(id) != 0) continue;
    const RecordSummary r = model_.RecordSummaryOf(id);
    resume_lines_.push_back(fmt::format("  partly recorded: {} ({} recorded over {}, {} chunks)", id,
                                        FormatLongDuration(r.recorded_s()),
                                        FormatLongDuration(r.span_s()), r.num_chunks));
  }
  if (done.count(kWelcomeId) != 0) AdvanceFrom(0);
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
  lines_.clear();
  if (current_ >= static_cast<int>(procedure_.steps.size())) {
    phase_ = Phase::kDone;
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

void WizardEngine::EnterPlace() {
  acq_.Stop();
  if (!acq_.noise_floor() && NeedsSensor(step().kind)) {
    acq_.MeasureNoiseFloor();
    phase_ = Phase::kQuiet;
    return;
  }
  phase_ = Phase::kPlace;
}

void WizardEngine::FinishStep(const std::string& outcome) {
  progressed_ = true;
  model_.RecordStepDone(step().id, outcome);
  AdvanceFrom(current_ + 1);
}

void WizardEngine::SkipStep() {
  const StepKind kind = step().kind;
  if (kind == StepKind::kFit || kind == StepKind::kReport) {
    problem_ = fmt::format("the {} cannot be skipped", StepKindToString(kind));
    return;
  }
  if (source_.bench() != nullptr && kind == StepKind::kTurntable) source_.bench()->StopTurntable();
  acq_.Stop();
  FinishStep("skipped");
}

// Back: within a step to its previous question; from a step's start to the nearest earlier
// step that has no accepted capture (a skipped one). Accepted captures are never replaced.
void WizardEngine::GoBack() {
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
  const std::vector<JournalCapture>& captures = model_.captures();
  const std::map<std::string, std::string>& done = model_.done_steps();
  for (int i = current_ - 1; i >= 0; --i) {
    const ProcedureStep& s = procedure_.steps[static_cast<size_t>(i)];
    const bool has_capture = std::any_of(captures.begin(), captures.end(),
                                         [&](const JournalCapture& c) { return c.step_id == s.id; });
    // A record that ran to its end is kept like an accepted capture.
    const auto d = done.find(s.id);
    const bool recorded = s.kind == StepKind::kRecord && d != done.end() && d->second != "skipped";
    if (IsCaptureStep(s.kind) && !has_capture && !recorded) {
      EnterStep(i);
      return;
    }
  }
  problem_ = "nothing to go back to: every earlier capture and record is recorded and is kept";
}

void WizardEngine::Quit() {
  acq_.Stop();
  quit_ = true;
  phase_ = Phase::kDone;
}

// ---- captures -------------------------------------------------------------------------------

CaptureRequest WizardEngine::MakeRequest() const {
  const ProcedureStep& s = step();
  CaptureRequest r;
  r.id = next_capture_id_;
  r.label = s.pose_name.empty() ? s.title : s.pose_name;
  r.duration_s = s.duration_s;
  r.timeout_s = s.timeout_s;
  if (s.kind == StepKind::kTurntable) {
    r.kind = CaptureKind::kTurntable;
    r.turntable.radius_m = radius_m_;
    r.turntable.rpm = rpm_;
    r.turntable.radial_axis = SensorAxisVector(s.radial_axis);
    r.turntable.up_axis = SensorAxisVector(s.up_axis);
  } else {
    r.expected = NamedPose{s.pose_name.empty() ? DescribeUp(s.up) : s.pose_name, s.up};
  }
  return r;
}

CaptureContext WizardEngine::MakeContext() const {
  CaptureContext c;
  c.rough_model = procedure_.nominal;
  c.noise_floor = *acq_.noise_floor();
  // Leveling measures the same pose twice: no duplicate check there.
  if (step().kind != StepKind::kLevel) c.captured = captured_;
  for (const ProcedureStep& s : procedure_.steps)
    if (s.kind == StepKind::kStatic && (s.up.array().abs() > 1e-6).count() > 1)
      c.known_poses.push_back({s.pose_name, s.up});
  return c;
}

void WizardEngine::PlaceOnBench() {
  BenchControl* bench = source_.bench();
  if (bench == nullptr) return;
  const ProcedureStep& s = step();
  if (s.kind == StepKind::kTurntable) {
    bench->PlaceTurntable(radius_m_, rpm_, s.radial_axis, s.up_axis);
  } else {
    bench->PlaceStatic(s.up);
  }
}

void WizardEngine::StartCaptureEngine() {
  CaptureEngineOptions o;
  o.stability.std_multiplier = procedure_.std_multiplier;
  o.stability.trend_multiplier = procedure_.trend_multiplier;
  o.orientation.tolerance_deg = procedure_.orientation_tolerance_deg;
  o.turntable.gravity_mps2 = options_.gravity.gravity_mps2;
  o.turntable.centripetal_tolerance = procedure_.turntable_tolerance;
  o.screening.adc_range = procedure_.adc_range;
  acq_.StartCapture(MakeRequest(), o, MakeContext());
  problem_.clear();
  hint_.clear();
  phase_ = Phase::kCapture;
}

// The operator says the sensor is in place (on the sim, this places it). A record resumed
// after an interruption assumes the sensor was left where it was: it is not placed again.
void WizardEngine::BeginCapture() {
  if (step().kind == StepKind::kRecord) {
    if (!RecordResumable()) PlaceOnBench();
    StartRecord();
    return;
  }
  PlaceOnBench();
  StartCaptureEngine();
}

// ---- records --------------------------------------------------------------------------------

bool WizardEngine::RecordResumable() const {
  return model_.RecordSummaryOf(step().id).num_chunks > 0;
}

void WizardEngine::StartRecord() {
  const ProcedureStep& s = step();
  RecordStepWriterOptions o;
  o.duration_s = s.duration_s;
  o.chunk_s = s.chunk_s;
  o.noise_std_counts = acq_.noise_floor()->std_counts;
  o.wall_now_s = options_.wall_now_s;
  // A fresh placement lets the hand go first; a resumed record goes on at once.
  const bool settle = !RecordResumable();
  acq_.StartRecord(std::make_unique<RecordStepWriter>(model_, s.id, o), settle);
  problem_.clear();
  hint_.clear();
  phase_ = Phase::kRecord;
  // Killed after the last chunk but before the step was marked done: nothing left to record.
  if (acq_.record().complete()) FinishRecord();
}

void WizardEngine::FinishRecord() {
  const std::string outcome = acq_.record().Outcome();
  acq_.Stop();
  FinishStep(outcome);
}

// What the acquisition reports, acted on.
void WizardEngine::OnAcquisition(AcquisitionEvent event) {
  switch (event) {
    case AcquisitionEvent::kNoiseFloorMeasured: phase_ = Phase::kPlace; break;
    case AcquisitionEvent::kCaptureAccepted: OnCaptureAccepted(); break;
    case AcquisitionEvent::kCaptureRejected:
      problem_ = acq_.reason();
      hint_ = step().kind == StepKind::kTurntable
                  ? "check the mounting, radius and speed; Enter tries again, b re-enters the values"
                  : fmt::format("put the prism with {} and let go; Enter tries again", MakeRequest().expected.name);
      phase_ = Phase::kProblem;
      break;
    case AcquisitionEvent::kCaptureRetrying:
      problem_ = acq_.reason();
      hint_ = "retrying by itself once the sensor is still again";
      break;
    case AcquisitionEvent::kCapturing:
      problem_.clear();
      hint_.clear();
      break;
    case AcquisitionEvent::kRecordComplete: FinishRecord(); break;
    case AcquisitionEvent::kNone: break;
  }
}

void WizardEngine::OnCaptureAccepted() {
  Capture capture = acq_.TakeCapture();
  const ProcedureStep& s = step();
  if (s.kind == StepKind::kLevel) {
    OnLevelCapture(capture.stats().mean_counts);
    return;
  }
  if (s.kind == StepKind::kTurntable) {
    capture.up_axis = s.up_axis;
    model_.RecordInput(s.id, "radius_m", fmt::format("{}", radius_m_));
    model_.RecordInput(s.id, "rpm", fmt::format("{}", rpm_));
  }
  // Recorded before moving on: a crash after this line loses nothing.
  progressed_ = true;
  model_.RecordCapture(s.id, capture);
  if (capture.kind == CaptureKind::kStatic)
    captured_.push_back({capture.id, capture.label, MeasuredUp(capture, procedure_.nominal)});
  next_capture_id_ = capture.id + 1;
  if (s.kind == StepKind::kTurntable && source_.bench() != nullptr) source_.bench()->StopTurntable();
  AdvanceFrom(current_ + 1);
}

void WizardEngine::OnLevelCapture(const Eigen::Vector3d& mean_counts) {
  if (!level_first_counts_) {
    level_first_counts_ = mean_counts;
    phase_ = Phase::kLevelTurn;
    return;
  }
  level_tilt_deg_ = ReversalTiltDeg(*level_first_counts_, mean_counts, procedure_.nominal);
  const std::string advice = LevelingAdvice(level_tilt_deg_, step().tolerance_deg);
  level_ok_ = advice.empty();
  problem_ = level_ok_ ? "" : "the table is not level: " + advice;
  hint_ = level_ok_ ? "" : "adjust the feet, then Enter to measure again (s skips leveling)";
  level_first_counts_.reset();
  phase_ = Phase::kLevelResult;
}

// ---- fit, diagnosis, report -----------------------------------------------------------------

// The steps that compute (calibration_steps.h); the engine only shows what they say.
void WizardEngine::Show(StepOutcome outcome) {
  phase_ = Phase::kResult;
  lines_ = std::move(outcome.lines);
  problem_ = std::move(outcome.problem);
  hint_ = std::move(outcome.hint);
}

void WizardEngine::RunFit() { Show(steps_.Fit()); }

void WizardEngine::RunDiagnosis() { Show(steps_.Diagnosis()); }

void WizardEngine::RunReport() {
  ReportMeta meta;
  meta.session_path = options_.report_beside;
  meta.procedure = procedure_.title;
  meta.source = source_.Describe();
  meta.date_utc = UtcNowIso8601();
  Show(steps_.Report(adopt_effects_, meta));
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
  UpdateLive(chunk);
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
    OnAcquisition(acq_.Feed(chunk));
}

// ---- intents --------------------------------------------------------------------------------

void WizardEngine::Handle(const Intent& intent) {
  if (phase_ == Phase::kDone) return;
  if (intent.kind == IntentKind::kQuit) {
    Quit();
    return;
  }
  switch (phase_) {
    case Phase::kWelcome: HandleWelcome(intent); return;
    case Phase::kRadius:
    case Phase::kRpm: HandleTurntableInput(intent); return;
    case Phase::kResult: HandleResult(intent); return;
    default: HandleCaptureIntent(intent); return;
  }
}

// Device, operator and place: what the report's identification names (the place, the lab
// where the gravity was taken, beside the gravity itself).
constexpr int kWelcomeFields = 3;

WizardEngine::WelcomeField WizardEngine::Welcome(int field) const {
  switch (field) {
    case 0: return {"device", "Device serial number", options_.default_device};
    case 1: return {"operator", "Operator", options_.default_operator};
    default: return {"place", "Place (lab, bench)", options_.default_place};
  }
}

void WizardEngine::HandleWelcome(const Intent& intent) {
  if (intent.kind == IntentKind::kBack) {
    welcome_field_ = std::max(0, welcome_field_ - 1);
    return;
  }
  const WelcomeField field = Welcome(welcome_field_);
  std::string value = intent.kind == IntentKind::kSubmitText ? intent.text : "";
  if (value.empty()) value = field.default_value;
  model_.RecordInput(kWelcomeId, field.key, value);
  if (welcome_field_ + 1 < kWelcomeFields) {
    ++welcome_field_;
    return;
  }
  model_.RecordStepDone(kWelcomeId, "ok");
  AdvanceFrom(0);
}

void WizardEngine::HandleTurntableInput(const Intent& intent) {
  if (intent.kind == IntentKind::kSkip) return SkipStep();
  if (intent.kind == IntentKind::kBack) return GoBack();
  if (intent.kind != IntentKind::kAccept && intent.kind != IntentKind::kSubmitText) return;
  const bool radius = phase_ == Phase::kRadius;
  const std::string text = intent.kind == IntentKind::kSubmitText ? intent.text : "";
  const double fallback = radius ? radius_m_ : rpm_;
  const QuantityResult q = text.empty() ? QuantityResult{fallback, ""}
                                        : (radius ? ParseRadius(text) : ParseRpm(text));
  if (!q.ok()) {
    input_error_ = q.error;
    return;
  }
  input_error_.clear();
  (radius ? radius_m_ : rpm_) = q.value;
  if (radius) {
    phase_ = Phase::kRpm;
    return;
  }
  TurntableSetup setup;
  setup.radius_m = radius_m_;
  setup.rpm = rpm_;
  setup.radial_axis = SensorAxisVector(step().radial_axis);
  setup.up_axis = SensorAxisVector(step().up_axis);
  TurntableStabilityOptions o;
  o.gravity_mps2 = options_.gravity.gravity_mps2;
  const std::string why = CheckTurntableAgainstRange(setup, procedure_.range_g, procedure_.nominal,
                                                     procedure_.adc_range, o);
  if (!why.empty()) {
    input_error_ = why;
    phase_ = Phase::kRadius;
    return;
  }
  EnterPlace();
}

void WizardEngine::HandleResult(const Intent& intent) {
  const StepKind kind = step().kind;
  if (intent.kind == IntentKind::kBack) return GoBack();
  if (intent.kind == IntentKind::kSkip) return SkipStep();
  if (intent.kind == IntentKind::kRetry) return EnterStep(current_);
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

void WizardEngine::HandleCaptureIntent(const Intent& intent) {
  if (intent.kind == IntentKind::kSkip) return SkipStep();
  if (intent.kind == IntentKind::kBack) return GoBack();
  const bool accept = intent.kind == IntentKind::kAccept || intent.kind == IntentKind::kSubmitText;
  switch (phase_) {
    case Phase::kPlace:
    case Phase::kProblem:
    case Phase::kLevelTurn:
      if (accept || intent.kind == IntentKind::kRetry) BeginCapture();
      return;
    case Phase::kCapture:
      if (intent.kind == IntentKind::kRetry) BeginCapture();
      return;
    case Phase::kRecord: return;  // a record runs to its end (s, b and q aside)
    case Phase::kLevelResult:
      if (intent.kind == IntentKind::kRetry || (accept && !level_ok_)) return EnterPlace();
      if (accept) {
        FinishStep(fmt::format("level: tilt {:.2f} deg about x, {:.2f} deg about y",
                               level_tilt_deg_.x(), level_tilt_deg_.y()));
      }
      return;
    default: return;
  }
}

}  // namespace accelcal
