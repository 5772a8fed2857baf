// The wizard engine's acquiring steps: the noise floor, captures (static, turntable, the
// leveling's two readings) and records, and what the operator's keys do while they run.
#include <algorithm>
#include <cmath>

#include <fmt/core.h>
#include <fmt/format.h>

#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/acquire/source/discard_backlog.h"
#include "accelcal/app/wizard/capture_messages.h"
#include "accelcal/app/wizard/leveling.h"
#include "accelcal/app/wizard/pose_setting.h"
#include "accelcal/app/wizard/session_settings.h"
#include "accelcal/app/wizard/wizard_engine.h"

namespace accelcal {
namespace {

bool NeedsSensor(StepKind kind) {
  return kind == StepKind::kStatic || kind == StepKind::kRecord || kind == StepKind::kTurntable ||
         kind == StepKind::kLevel;
}

}  // namespace

// ---- the noise floor ------------------------------------------------------------------------

void WizardEngine::EnterPlace() {
  acq_.Stop();
  if (!floor_guard_.floor() && NeedsSensor(step().kind)) {
    phase_ = Phase::kQuietReady;
    return;
  }
  phase_ = Phase::kPlace;
}

void WizardEngine::OnQuietMeasured() {
  const NoiseFloorJudgement j = floor_guard_.Judge(acq_.quiet_samples());
  if (!j.ok) {
    problem_ = j.reason;
    hint_ = "keep hands off the bench and stop what shakes it, then Enter measures again";
    phase_ = Phase::kQuietReady;
    return;
  }
  // A lower floor of an earlier run (proved by its captures) wins over a new measurement above it.
  if (lowered_floor_) {
    NoiseFloor f = *floor_guard_.floor();
    for (int a = 0; a < 3; ++a) f.std_counts[a] = std::min(f.std_counts[a], lowered_floor_->std_counts[a]);
    if (f.std_counts != floor_guard_.floor()->std_counts) f.source += ", with the lower floor of an earlier run";
    floor_guard_.Restore(f);
  }
  problem_.clear();
  hint_.clear();
  model_.RecordInput(kNoiseFloorStepId, "std_counts", TriadText(floor_guard_.floor()->std_counts));
  floor_lines_ = {"Noise floor: " + floor_guard_.Describe()};
  phase_ = Phase::kPlace;
}

// After a static capture: the floor checked against it, lowered if it proves too high, and
// the captures judged with the old floor judged again; those that fail are left out and their
// steps captured again.
void WizardEngine::RecheckNoiseFloor(const Capture& latest) {
  std::vector<const Capture*> used;
  for (const JournalCapture& c : model_.captures())
    if (c.capture.kind == CaptureKind::kStatic && model_.LeftOutReason(c).empty() && !c.superseded())
      used.push_back(&c.capture);
  const NoiseFloorRecheck r = floor_guard_.Recheck(latest, used);
  if (!r.lowered) return;
  model_.RecordInput(kNoiseFloorStepId, "lowered_std_counts", TriadText(r.after.std_counts));
  model_.RecordInput(kNoiseFloorStepId, "lowered", r.note);
  lowered_floor_ = r.after;
  floor_lines_ = {"Noise floor: " + floor_guard_.Describe(), r.note};
  std::vector<std::string> again;
  for (const RejudgedCapture& f : r.failing) {
    for (const JournalCapture& c : model_.captures()) {
      if (c.capture.id != f.capture_id) continue;
      model_.MarkLeftOut(c, f.reason + " (judged again against the lowered noise floor)");
      again.push_back(c.capture.label);
      std::erase_if(captured_, [&](const CapturedPose& p) { return p.capture_id == c.capture.id; });
    }
  }
  if (!again.empty())
    floor_lines_.push_back(fmt::format("Judged again with it, not still after all, left out and to be "
                                       "captured again: {}.", fmt::join(again, ", ")));
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
  c.noise_floor = *floor_guard_.floor();
  // Leveling measures the same pose twice: no duplicate check there.
  if (step().kind != StepKind::kLevel) c.captured = captured_;
  // A redo takes the same pose again: the capture it replaces is no duplicate.
  std::erase_if(c.captured, [&](const CapturedPose& p) { return Redoing() && p.capture_id == redo_capture_id_; });
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
    // The leveling's second reading: the prism turned 180 deg about the vertical.
    const bool turned = s.kind == StepKind::kLevel && level_first_counts_.has_value();
    bench->PlaceStatic(s.up, turned ? M_PI : 0.0);
  }
}

void WizardEngine::StartCaptureEngine() {
  CaptureEngineOptions o;
  o.stability.std_multiplier = procedure_.std_multiplier;
  o.stability.trend_multiplier = procedure_.trend_multiplier;
  o.orientation.tolerance_deg = procedure_.orientation_tolerance_deg;
  o.turntable.gravity_mps2 = gravity_.gravity_mps2;
  o.turntable.centripetal_tolerance = procedure_.turntable_tolerance;
  o.turntable.max_tilt_deg = procedure_.turntable_tilt_tolerance_deg;
  o.screening.adc_range = procedure_.adc_range;
  acq_.StartCapture(MakeRequest(), o, MakeContext(), SteadyNowS());
  problem_.clear();
  hint_.clear();
  detail_.clear();
  phase_ = Phase::kCapture;
}

// The operator says the sensor is in place (on the sim, this places it). A record resumed
// after an interruption assumes the sensor was left where it was: it is not placed again.
void WizardEngine::BeginCapture() {
  DiscardBacklog(source_);  // judged are the samples taken after the answer, not before
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

// How long a record waits on a silent link (connected, sending nothing readable) before it
// stops: the slack its procedure gives beyond the record's own length (timeout_s - duration_s:
// the procedure's capture_timeout_s, 60 s, unless the step sets timeout_s), at least 1 s.
double WizardEngine::RecordSilenceTimeoutS(const ProcedureStep& s) {
  return std::max(1.0, s.timeout_s - s.duration_s);
}

void WizardEngine::StartRecord() {
  const ProcedureStep& s = step();
  RecordStepWriterOptions o;
  o.duration_s = s.duration_s;
  o.chunk_s = s.chunk_s;
  o.noise_std_counts = floor_guard_.floor()->std_counts;
  o.wall_now_s = options_.wall_now_s;
  // A fresh placement lets the hand go first; a resumed record goes on at once.
  const bool settle = !RecordResumable();
  acq_.StartRecord(std::make_unique<RecordStepWriter>(model_, s.id, o), settle, SteadyNowS(),
                   RecordSilenceTimeoutS(s));
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
    case AcquisitionEvent::kNoiseFloorMeasured: OnQuietMeasured(); break;
    case AcquisitionEvent::kCaptureAccepted: OnCaptureAccepted(); break;
    case AcquisitionEvent::kCaptureRejected: OnCaptureRejected(); break;
    case AcquisitionEvent::kCaptureRetrying:
      // Said in words on the capture screen (capture_messages.h): not a failure to stop on.
      problem_.clear();
      hint_.clear();
      break;
    case AcquisitionEvent::kCapturing:
      problem_.clear();
      hint_.clear();
      break;
    case AcquisitionEvent::kRecordComplete: FinishRecord(); break;
    case AcquisitionEvent::kNoiseFloorSilent:
      problem_ = acq_.reason();
      hint_ = "check the cable or the sample server; Enter measures again, q leaves";
      phase_ = Phase::kQuietReady;
      break;
    case AcquisitionEvent::kRecordSilent:
      // Stopped, the chunk being filled committed: Enter resumes it (with the gap stated).
      problem_ = acq_.reason();
      hint_ = "check the cable or the sample server; Enter goes on with the record, q leaves "
              "(what was recorded is in the session)";
      phase_ = Phase::kProblem;
      break;
    case AcquisitionEvent::kNone: break;
  }
}

void WizardEngine::OnCaptureRejected() {
  const CaptureMessage said = DescribeEnded(acq_.reason(), step().timeout_s);
  problem_ = said.text;
  detail_ = said.detail;
  phase_ = Phase::kProblem;
  if (acq_.ended_silent()) {
    hint_ = "check the cable or the sample server; Enter tries again, q leaves";
    return;
  }
  if (step().kind != StepKind::kTurntable) {
    hint_ = IsTiltedPose(step().up)
                ? fmt::format("set the prism {} and let go; Enter tries again", PrismSetting(step().up, step().pose_name))
                : fmt::format("put the prism with {} and let go; Enter tries again", MakeRequest().expected.name);
    return;
  }
  const TurntableVerdict& v = acq_.last_turntable();
  hint_ = !v.mounted_as_asked && !v.mounting_found.empty()
              ? fmt::format("stop the table, mount the sensor {} as asked and start the table again; "
                            "Enter tries again", step().pose_name)
          : !v.level ? "level the turntable; Enter tries again"
                     : "check the mounting, radius and speed; Enter tries again, b re-enters the values";
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
    // The swing removed from the samples, so that the raw readings can be rebuilt.
    const TurntableVerdict& v = acq_.last_turntable();
    model_.RecordInput(s.id, "table_tilt_deg", fmt::format("{:.4f}", v.tilt_deg));
    model_.RecordInput(s.id, "swing_removed_counts",
                       fmt::format("t0 {:.6f} w {:.9g} cos {} sin {}", v.swing.t0_s, v.swing.w_rad_per_s,
                                   TriadText(v.swing.cos_counts), TriadText(v.swing.sin_counts)));
  }
  // Recorded before moving on: a crash after this line loses nothing.
  progressed_ = true;
  RecordAcceptedCapture(capture);
  ConfirmCapture(capture);
  clock_.MarkCapture(capture.stats().t_last_s, model_);
  if (capture.kind == CaptureKind::kStatic) {
    captured_.push_back({capture.id, capture.label, MeasuredUp(capture)});
    RecheckNoiseFloor(capture);
  }
  next_capture_id_ = capture.id + 1;
  if (s.kind == StepKind::kTurntable && source_.bench() != nullptr) source_.bench()->StopTurntable();
  // Back to the first step without a usable capture: one left out by the lowered floor
  // comes before the next new one.
  AdvanceFrom(0);
}

void WizardEngine::OnLevelCapture(const Eigen::Vector3d& mean_counts) {
  if (!level_first_counts_) {
    level_first_counts_ = mean_counts;
    phase_ = Phase::kLevelTurn;
    return;
  }
  level_tilt_deg_ = ReversalTiltDeg(*level_first_counts_, mean_counts, procedure_.nominal);
  level_offset_ = ReversalOffset(*level_first_counts_, mean_counts, procedure_.nominal);
  const std::string advice = LevelingAdvice(level_tilt_deg_, step().tolerance_deg);
  level_ok_ = advice.empty();
  problem_ = level_ok_ ? "" : "the table is not level: " + advice;
  hint_ = level_ok_ ? "" : "adjust the feet, then Enter to measure again (s skips leveling)";
  level_first_counts_.reset();
  phase_ = Phase::kLevelResult;
}

void WizardEngine::HandleCaptureIntent(const Intent& intent) {
  if (intent.kind == IntentKind::kSkip) return AskSkip();
  if (intent.kind == IntentKind::kBack) return GoBack();
  const bool accept = intent.kind == IntentKind::kAccept || intent.kind == IntentKind::kSubmitText;
  switch (phase_) {
    case Phase::kQuietReady:
      if (accept || intent.kind == IntentKind::kRetry) {
        DiscardBacklog(source_);
        acq_.MeasureNoiseFloor(SteadyNowS(), step().timeout_s);
        phase_ = Phase::kQuiet;
      }
      return;
    case Phase::kProblem:
      if (!(accept || intent.kind == IntentKind::kRetry)) return;
      // Refused for its tilt: the operator levels the turntable before trying again.
      if (step().kind == StepKind::kTurntable && !acq_.last_turntable().level &&
          source_.bench() != nullptr)
        source_.bench()->LevelTurntable();
      BeginCapture();
      return;
    case Phase::kPlace:
    case Phase::kLevelTurn:
      if (accept || intent.kind == IntentKind::kRetry) BeginCapture();
      return;
    case Phase::kCapture:
      if (intent.kind == IntentKind::kRetry) BeginCapture();
      return;
    case Phase::kRecord: return;  // a record runs to its end (s, b and q aside)
    case Phase::kLevelResult:
      if (intent.kind == IntentKind::kRetry) return EnterPlace();
      if (accept && !level_ok_) {
        // The operator turns the feet as advised (on the virtual bench, its technician does).
        if (source_.bench() != nullptr) source_.bench()->AdjustTableFeet(level_tilt_deg_);
        return EnterPlace();
      }
      if (accept) {
        FinishStep(fmt::format("level: tilt {:.2f} deg about x, {:.2f} deg about y",
                               level_tilt_deg_.x(), level_tilt_deg_.y()));
      }
      return;
    default: return;
  }
}

}  // namespace accelcal
