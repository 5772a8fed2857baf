#include "accelcal/app/wizard/steps/acquiring_step.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/acquire/source/discard_backlog.h"
#include "accelcal/app/wizard/capture_messages.h"
#include "accelcal/app/wizard/pose_setting.h"
#include "accelcal/app/wizard/time_estimate.h"

namespace accelcal {

// ---- keys -----------------------------------------------------------------------------------

void AcquiringStep::Handle(const Intent& intent) {
  if (phase_ == Phase::kOwn) return HandleOwn(intent);
  if (intent.kind == IntentKind::kSkip) return session_.sequence.AskSkip();
  if (intent.kind == IntentKind::kBack) return session_.sequence.GoBack();
  const bool accept = intent.kind == IntentKind::kAccept || intent.kind == IntentKind::kSubmitText;
  const bool again = accept || intent.kind == IntentKind::kRetry;
  switch (phase_) {
    case Phase::kNoiseFloor:
      // Refused again and again: Enter no longer measures the same bench (r still does).
      if (accept && !session_.noise_floor.measuring() && session_.noise_floor.gives_up())
        return session_.sequence.SaveAndLeave();
      if (again && !session_.noise_floor.measuring()) {
        DiscardBacklog(session_.source);  // the floor of the bench at rest now, not while asked
        session_.noise_floor.Measure(step_.timeout_s);
      }
      return;
    case Phase::kProblem:
      if (!again) return;
      // Refused again and again: Enter no longer repeats what failed (r still does).
      if (accept && refusals_in_row_ >= kRefusalsBeforeLeaving) return session_.sequence.SaveAndLeave();
      BeforeRetry();
      Begin();
      return;
    case Phase::kPlace:
      if (again) Begin();
      return;
    case Phase::kCapture:
      if (intent.kind == IntentKind::kRetry) Begin();
      return;
    case Phase::kOwn: return;
  }
}

void AcquiringStep::HandleOwn(const Intent& intent) {
  if (intent.kind == IntentKind::kSkip) return session_.sequence.AskSkip();
  if (intent.kind == IntentKind::kBack) return session_.sequence.GoBack();
}

bool AcquiringStep::BackWithin() {
  if (phase_ != Phase::kCapture && phase_ != Phase::kProblem) return false;
  BackFromCapture();
  return true;
}

bool AcquiringStep::AtStart() const {
  return phase_ == Phase::kPlace || (phase_ == Phase::kNoiseFloor && !session_.noise_floor.measuring());
}

// A phase of the kind's own (a question, the reversal) starts the step again; else the placement.
void AcquiringStep::KeepAfterSkipDeclined() {
  if (phase_ == Phase::kOwn) return session_.sequence.RestartStep();
  EnterPlace();
}

// ---- acquiring ------------------------------------------------------------------------------

bool AcquiringStep::Acquiring() const {
  return phase_ == Phase::kCapture || (phase_ == Phase::kNoiseFloor && session_.noise_floor.measuring());
}

void AcquiringStep::EnterPlace() {
  session_.acq.Stop();
  refusals_in_row_ = 0;
  if (!session_.noise_floor.floor()) {
    session_.noise_floor.Ask();
    phase_ = Phase::kNoiseFloor;
    return;
  }
  phase_ = Phase::kPlace;
}

// Without a noise floor (the source ended while it was measured) it is measured first. What a
// live source sent while the question waited is dropped: judged are the samples taken after the
// answer (the pose of before is not the one asked for).
void AcquiringStep::Begin() {
  if (!session_.noise_floor.floor()) return EnterPlace();
  DiscardBacklog(session_.source);
  BeginCapture();
}

void AcquiringStep::BeginCapture() {
  PlaceOnBench();
  StartCaptureEngine();
}

void AcquiringStep::PlaceOnBench() {
  if (BenchControl* bench = session_.source.bench()) bench->PlaceStatic(step_.up, 0.0);
}

CaptureRequest AcquiringStep::BaseRequest() const {
  CaptureRequest r;
  r.id = session_.next_capture_id;
  r.label = step_.pose_name.empty() ? step_.title : step_.pose_name;
  r.duration_s = step_.duration_s;
  r.timeout_s = step_.timeout_s;
  return r;
}

CaptureRequest AcquiringStep::MakeRequest() const {
  CaptureRequest r = BaseRequest();
  r.expected = NamedPose{step_.pose_name.empty() ? DescribeUp(step_.up) : step_.pose_name, step_.up};
  return r;
}

void AcquiringStep::StartCaptureEngine() {
  const Procedure& p = session_.procedure;
  CaptureEngineOptions o;
  o.stability.std_multiplier = p.std_multiplier;
  o.stability.trend_multiplier = p.trend_multiplier;
  o.orientation.tolerance_deg = p.orientation_tolerance_deg;
  o.turntable.gravity_mps2 = session_.gravity.gravity_mps2;
  o.turntable.centripetal_tolerance = p.turntable_tolerance;
  o.turntable.max_tilt_deg = p.turntable_tilt_tolerance_deg;
  o.screening.adc_range = p.adc_range;
  CaptureContext c;
  c.rough_model = p.nominal;
  c.noise_floor = *session_.noise_floor.floor();
  if (ChecksDuplicates()) c.captured = session_.captured;
  // A redo takes the same pose again: the capture it replaces is no duplicate.
  if (const int replaced = session_.sequence.ReplacedCaptureId(); replaced != 0)
    std::erase_if(c.captured, [&](const CapturedPose& pose) { return pose.capture_id == replaced; });
  for (const ProcedureStep& s : p.steps)
    if (IsStaticPoseStep(s.kind) && (s.up.array().abs() > 1e-6).count() > 1)
      c.known_poses.push_back({s.pose_name, s.up});
  session_.acq.StartCapture(MakeRequest(), o, c, SteadyNowS());
  session_.screen.problem.clear();
  session_.screen.hint.clear();
  session_.screen.detail.clear();
  phase_ = Phase::kCapture;
}

// What the acquisition reports, acted on.
void AcquiringStep::OnAcquisition(AcquisitionEvent event) {
  switch (event) {
    case AcquisitionEvent::kNoiseFloorMeasured:
      if (session_.noise_floor.OnMeasured()) phase_ = Phase::kPlace;
      break;
    case AcquisitionEvent::kCaptureAccepted:
      refusals_in_row_ = 0;
      accepted_elapsed_s_ = session_.acq.capturing() ? session_.acq.capture_snapshot().elapsed_s : kNaN;
      OnCaptureAccepted(session_.acq.TakeCapture());
      break;
    case AcquisitionEvent::kCaptureRejected: OnCaptureRejected(); break;
    case AcquisitionEvent::kCaptureRetrying:
      // Said in words on the capture screen (capture_messages.h): not a failure to stop on.
    case AcquisitionEvent::kCapturing:
      session_.screen.problem.clear();
      session_.screen.hint.clear();
      break;
    case AcquisitionEvent::kNoiseFloorSilent: session_.noise_floor.OnSilent(); break;
    case AcquisitionEvent::kRecordComplete:
    case AcquisitionEvent::kRecordSilent:
    case AcquisitionEvent::kNone: break;
  }
}

// Said on the next screen until a key: what was taken, with its figures. |a| is from the
// procedure's nominal (datasheet) model, the fit comes later: a few % off, said so.
void AcquiringStep::KeepCapture(const Capture& capture) {
  session_.sequence.RecordCapture(capture);  // recorded before moving on: a crash after it loses nothing
  const CaptureStats& st = capture.stats();
  const double covered_s =
      st.n > 1 ? (st.t_last_s - st.t_first_s) * static_cast<double>(st.n) / static_cast<double>(st.n - 1) : 0.0;
  const double a_mps2 = session_.procedure.nominal.Calibrate(st.mean_counts).norm();
  const double noise_counts = std::sqrt(st.StdCounts().squaredNorm() / 3.0);
  session_.screen.notice = fmt::format("{} done: {:.1f} s, |a| ~{:.2f} m/s^2 by the datasheet, noise {:.1f} counts",
                                       capture.label, covered_s, a_mps2, noise_counts);
  session_.clock.MarkCapture(capture.stats().t_last_s, session_.model);
  session_.bench_plan.RecordSpent(session_, step_, capture, accepted_elapsed_s_);
}

CaptureRequest AcquiringStep::Planned(CaptureRequest request) const {
  session_.bench_plan.Refresh(session_);
  session_.bench_plan.Apply(step_, &request);
  return request;
}

void AcquiringStep::OnCaptureRejected() {
  const CaptureMessage said = RejectedMessage();
  session_.screen.problem = said.text;
  session_.screen.detail = said.detail;
  phase_ = Phase::kProblem;
  session_.screen.hint = session_.acq.ended_silent()
                             ? "check the cable or the sample server; Enter tries again, q leaves"
                             : RejectedHint();
  if (++refusals_in_row_ >= kRefusalsBeforeLeaving)
    session_.screen.hint = fmt::format(
        "not accepted {} times in a row: {} (the same again will not do); r tries again, s skips it, "
        "Enter saves and quits (the session resumes at this step)",
        refusals_in_row_, ProblemToCheck());
}

// What the technician checks before trying again: the hint without its "Enter tries again".
std::string AcquiringStep::ProblemToCheck() const {
  std::string check = session_.acq.ended_silent() ? "check the cable or the sample server" : RejectedHint();
  if (const size_t cut = check.find("; Enter tries again"); cut != std::string::npos) check.resize(cut);
  return check;
}

// The give-up the capture had (the procedure's, a settling wait's more: BenchPlan::GiveUpS).
CaptureMessage AcquiringStep::RejectedMessage() const {
  const double timeout_s = session_.acq.capture_timeout_s();
  return DescribeEnded(session_.acq.reason(), std::isfinite(timeout_s) ? timeout_s : step_.timeout_s);
}

// A capture given up because the sensor was never still: what to do about the bench (placing the
// prism again would not help); else how to place it.
std::string AcquiringStep::RejectedHint() const {
  if (const std::string bench = StillnessHint(session_.acq.reason()); !bench.empty()) return bench;
  return IsTiltedPose(step_.up)
             ? fmt::format("set the prism {} and let go; Enter tries again", PrismSetting(step_.up, step_.pose_name))
             : fmt::format("put the prism with {} and let go; Enter tries again", MakeRequest().expected.name);
}

// ---- view -----------------------------------------------------------------------------------

void AcquiringStep::SetHeader(WizardView& v) const {
  v.step_title = step_.title;
  v.pose_name = step_.pose_name;
  v.expected_up = step_.up;
}

void AcquiringStep::SetView(WizardView& v) const {
  switch (phase_) {
    case Phase::kNoiseFloor: return session_.noise_floor.SetView(v);
    case Phase::kPlace: return SetPlaceView(v);
    case Phase::kCapture:
    case Phase::kProblem: return SetCaptureView(v);
    case Phase::kOwn: return SetOwnView(v);
  }
}

// While the noise floor is measured no capture is waited for.
double AcquiringStep::WaitingCaptureS(bool on_screen) const {
  return on_screen && phase_ == Phase::kNoiseFloor ? kNaN : CaptureS();
}

void AcquiringStep::SetCaptureView(WizardView& v) const {
  v.screen = phase_ == Phase::kProblem ? WizardScreen::kError : WizardScreen::kCapturing;
  v.keys = {{"r", "retry"}, {"s", "skip"}, {"b", "back"}, {"q", "save and quit"}};
  if (phase_ == Phase::kProblem) {
    const bool leaves = refusals_in_row_ >= kRefusalsBeforeLeaving;
    v.prompt = leaves ? fmt::format("The capture was not accepted {} times in a row.", refusals_in_row_)
                      : "The capture was not accepted.";
    v.detail = session_.screen.detail;
    v.keys.insert(v.keys.begin(), KeyHint{"Enter", leaves ? "save and quit" : "try again"});
    return;
  }
  const CaptureSnapshot snap = session_.acq.capture_snapshot();
  const bool turning = Turning();
  const CaptureMessage said = DescribeCapture(snap, turning);
  const bool capturing = snap.state == CaptureState::kCapturing;
  // Time: the capture's seconds left once it captures, the give-up's countdown (sample time,
  // as the capture engine counts it), and the session's estimate.
  const double capture_s = CaptureS();
  v.capture_left_s = capturing ? capture_s * (1.0 - snap.progress) : kNaN;
  // The capture's own give-up (the procedure's, BenchPlan::GiveUpS; a settling wait's more).
  v.give_up_in_s = std::max(session_.acq.capture_timeout_s() - snap.elapsed_s, 0.0);
  v.session_left_s = (capturing ? v.capture_left_s : capture_s) + session_.sequence.SessionLeftS(true);
  v.time_text = CaptureTimeText(capture_s, v.capture_left_s, v.give_up_in_s, v.session_left_s);
  // By the plan the bar fills toward "enough data" (the count the noise floor dictates).
  const std::string enough = session_.bench_plan.ProgressWords(snap.progress);
  const std::string filled = enough.empty() ? fmt::format("{:.0f} %", snap.progress * 100.0) : enough;
  v.prompt = fmt::format("{} {} (attempt {}): {}", CaptureStateToString(snap.state), step_.pose_name,
                         std::max(1, snap.attempts),
                         capturing ? fmt::format("{}, {:.0f} s left; {}", filled,
                                                 std::round(v.capture_left_s), said.text)
                                   : said.text);
  v.progress = snap.progress;
  v.waiting = said.waiting;
  v.detail = said.detail;
  if (!turning) v.stability = snap.stability.WorstRatio();
  v.stability_text = capturing ? (turning ? "turning steadily" : "still") : said.text;
}

double PlacedStepEstimateS(const ProcedureStep& step, const TimeAllowances& a) {
  return a.place_pose_s + a.settle_s + step.duration_s;
}

}  // namespace accelcal
