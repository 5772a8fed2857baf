// The wizard engine's view-model: what a front end draws, built from the engine's state.
#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "accelcal/app/wizard/capture_messages.h"
#include "accelcal/app/wizard/diagnosis_words.h"
#include "accelcal/app/wizard/leveling.h"
#include "accelcal/app/wizard/pose_setting.h"
#include "accelcal/app/wizard/time_estimate.h"
#include "accelcal/app/wizard/wizard_engine.h"

namespace accelcal {
namespace {

// The step's own keys, then skip, back and quit (always meaningful).
std::vector<KeyHint> WithNavigation(std::vector<KeyHint> keys) {
  keys.push_back({"s", "skip"});
  keys.push_back({"b", "back"});
  keys.push_back({"q", "save and quit"});
  return keys;
}

}  // namespace

// ---- view -----------------------------------------------------------------------------------

WizardView WizardEngine::View() const {
  WizardView v;
  v.session = options_.session_name;
  v.procedure = procedure_.title;
  v.resumed = resumed_;
  v.step_count = static_cast<int>(procedure_.steps.size()) + 1;
  v.step_index = std::min(current_ + 2, v.step_count);
  v.live_counts = live_counts_;
  if (live_counts_.allFinite())
    v.live_g = procedure_.nominal.Calibrate(live_counts_).norm() / gravity_.gravity_mps2;
  v.problem = problem_;
  v.hint = hint_;
  // The resume summary is shown until this run has recorded something of its own.
  if (resumed_ && !progressed_) v.lines = resume_lines_;
  const std::vector<std::string>& text = show_details_ ? details_ : lines_;
  v.lines.insert(v.lines.end(), text.begin(), text.end());
  // What the noise floor's checks said, beside the steps that acquire.
  if (phase_ != Phase::kResult && phase_ != Phase::kDone)
    v.lines.insert(v.lines.end(), floor_lines_.begin(), floor_lines_.end());
  v.noise_floor_text = floor_guard_.Describe();
  v.status = source_.Describe() + ": " + source_.status().BriefReport();
  SetStepView(v);
  SetPhaseView(v);
  SetTimeView(v);
  v.notice = notice_;
  AddRedoLines(v);
  // Leveling: the live tilt, without the sensor's own offset once a reversal has measured it
  // (before, it includes the offset: adjusting the feet by it chases the offset).
  if (current_ >= 0 && current_ < static_cast<int>(procedure_.steps.size()) &&
      step().kind == StepKind::kLevel && phase_ != Phase::kLevelResult && live_counts_.allFinite()) {
    if (level_offset_) {
      v.tilt_deg = TiltWithoutOffsetDeg(live_counts_, procedure_.nominal, *level_offset_);
      const Eigen::Vector2d offset_deg = OffsetAsTiltDeg(*level_offset_);
      v.tilt_note = fmt::format("sensor's offset (x {:.1f}, y {:.1f} deg) taken out", offset_deg.x(),
                                offset_deg.y());
    } else {
      v.tilt_deg = ApparentTiltDeg(live_counts_, procedure_.nominal);
      v.tilt_note = "includes the sensor's offset until the reversal";
    }
  }
  if (source_.status().link == LinkState::kDead && v.problem.empty()) {
    v.problem = "no samples: " + source_.status().link_error;
    v.hint = "check the cable or the sample server; the wizard goes on when samples return";
  }
  return v;
}

void WizardEngine::SetStepView(WizardView& v) const {
  if (current_ < 0) {
    v.step_title = "Welcome";
    return;
  }
  if (current_ >= static_cast<int>(procedure_.steps.size())) {
    v.step_title = "Done";
    return;
  }
  const ProcedureStep& s = step();
  v.step_title = s.title;
  v.pose_name = s.pose_name;
  if (s.kind == StepKind::kStatic || s.kind == StepKind::kRecord || s.kind == StepKind::kLevel)
    v.expected_up = s.up;
  if (s.kind == StepKind::kTurntable) v.expected_up = SensorAxisVector(s.up_axis);
}

void WizardEngine::SetPhaseView(WizardView& v) const {
  switch (phase_) {
    case Phase::kWelcome:
      return SetWelcomeView(v);
    case Phase::kQuietReady:
    case Phase::kQuiet:
      return SetQuietView(v);
    case Phase::kConfirmSkip:
      return SetConfirmSkipView(v);
    case Phase::kConfirmRedo:
      return SetConfirmRedoView(v);
    case Phase::kPlace:
      return SetPlaceView(v);
    case Phase::kLevelTurn:
    case Phase::kLevelResult:
      return SetLevelView(v);
    case Phase::kRadius:
    case Phase::kRpm:
      return SetInputView(v);
    case Phase::kCapture:
    case Phase::kProblem:
      return SetCaptureView(v);
    case Phase::kRecord:
      return SetRecordView(v);
    case Phase::kResult:
      return SetResultView(v);
    case Phase::kDone:
      return SetDoneView(v);
  }
}

void WizardEngine::SetWelcomeView(WizardView& v) const {
  const WelcomeField field = Welcome(welcome_field_);
  v.screen = WizardScreen::kWelcome;
  v.prompt = fmt::format("Welcome to {}.", procedure_.title);
  if (!input_note_.empty()) v.prompt += " " + input_note_;
  v.input = InputRequest{field.key, field.label, field.default_value, input_error_};
  v.keys = {{"Enter", "accept"}, {"b", "back"}, {"q", "save and quit"}};
}

void WizardEngine::SetQuietView(WizardView& v) const {
  if (phase_ == Phase::kQuietReady) {
    v.screen = WizardScreen::kPlacePose;
    v.prompt = fmt::format(
        "Noise floor: leave the sensor resting on the table, hands off, nothing shaking the bench "
        "(turntable stopped); press Enter to measure it ({:g} s).", options_.quiet_period_s);
    v.keys = WithNavigation({{"Enter", "measure"}});
    return;
  }
  v.screen = WizardScreen::kCapturing;
  v.prompt =
      fmt::format("Leave the sensor resting on the table: measuring the noise floor ({:g} s).",
                  options_.quiet_period_s);
  v.progress = acq_.quiet_progress();
  v.keys = {{"q", "save and quit"}};
}

void WizardEngine::SetConfirmSkipView(WizardView& v) const {
  v.screen = WizardScreen::kPlacePose;
  v.prompt = step().required
                 ? fmt::format("Skip '{}'? The procedure requires it: without it the report's verdict "
                               "is INCOMPLETE. Press s again to skip it, Enter to do it.", step().title)
                 : fmt::format("Skip '{}'? The report will list it as skipped. Press s again to skip "
                               "it, Enter to do it.", step().title);
  v.keys = {{"s", "skip it"}, {"Enter", "do it"}, {"q", "save and quit"}};
}

void WizardEngine::SetPlaceView(WizardView& v) const {
  v.screen = step().kind == StepKind::kTurntable ? WizardScreen::kMountTurntable
             : step().kind == StepKind::kLevel   ? WizardScreen::kLevel
                                                 : WizardScreen::kPlacePose;
  if (step().kind == StepKind::kRecord && RecordResumable()) {
    const RecordSummary r = model_.RecordSummaryOf(step().id);
    v.prompt = fmt::format("Resuming the {}: {} recorded of {}. Leave the sensor as it is and "
                           "press Enter to go on recording (the gap is recorded).",
                           step().title, FormatLongDuration(r.recorded_s()),
                           FormatLongDuration(step().duration_s));
    v.keys = WithNavigation({{"Enter", "resume"}});
    return;
  }
  v.prompt =
      step().kind == StepKind::kRecord
          ? fmt::format("Put the prism on the table with {} and let go; press Enter to start the "
                        "{} record.", step().pose_name, FormatLongDuration(step().duration_s))
      : step().kind == StepKind::kTurntable
          ? fmt::format(
                "Stop the table before you touch the sensor. Mount it with {} at {:g} mm from the "
                "axis, then start the table at {:g} rpm and wait for it to settle; press Enter "
                "when it turns steadily.",
                step().pose_name, radius_m_ * 1000.0, rpm_)
      : step().kind == StepKind::kLevel
          ? "Put the prism on the table with +z up and let go; press Enter to measure the tilt."
      : IsTiltedPose(step().up)
          ? fmt::format("Set the prism {} and let go; press Enter to capture.",
                        PrismSetting(step().up, step().pose_name))
          : fmt::format("Put the prism on the table with {} and let go; press Enter to capture.",
                        step().pose_name);
  v.keys = WithNavigation({{"Enter", "capture"}});
}

void WizardEngine::SetLevelView(WizardView& v) const {
  v.screen = WizardScreen::kLevel;
  if (phase_ == Phase::kLevelTurn) {
    v.prompt =
        "Turn the prism 180 deg about the vertical (still +z up); press Enter to measure again.";
    v.keys = WithNavigation({{"Enter", "measure"}});
    return;
  }
  v.tilt_deg = level_tilt_deg_;
  v.prompt = fmt::format("Tilt {:.2f} deg about x, {:.2f} deg about y (tolerance {:g} deg): {}.",
                         level_tilt_deg_.x(), level_tilt_deg_.y(), step().tolerance_deg,
                         level_ok_ ? "level; press Enter to continue" : "not level");
  v.keys =
      WithNavigation({{"Enter", level_ok_ ? "continue" : "measure again"}, {"r", "measure again"}});
}

void WizardEngine::SetInputView(WizardView& v) const {
  const bool radius = phase_ == Phase::kRadius;
  v.screen = WizardScreen::kInput;
  v.prompt = fmt::format("Turntable run with {}: stop the table before you touch the sensor.",
                         step().pose_name);
  if (!input_note_.empty()) v.prompt += " " + input_note_;
  v.input = InputRequest{
      radius ? "radius" : "rpm",
      radius ? "Radius from the spin axis to the sensor (e.g. 120 mm)"
             : "Table speed (e.g. 120 rpm, 2 rps or 2 Hz, 12.57 rad/s)",
      radius ? fmt::format("{:g} mm", radius_m_ * 1000.0) : fmt::format("{:g} rpm", rpm_),
      input_error_};
  v.keys = WithNavigation({{"Enter", "accept"}});
}

void WizardEngine::SetResultView(WizardView& v) const {
  const StepKind kind = step().kind;
  v.screen = kind == StepKind::kFit         ? WizardScreen::kFit
             : kind == StepKind::kDiagnosis ? WizardScreen::kDiagnosis
                                            : WizardScreen::kReport;
  if (!problem_.empty()) {
    v.prompt = "The session cannot go on from here as it is.";
    v.keys = WithNavigation({{"r", "retry"}});
    return;
  }
  const CalibrationOutcome* outcome = steps_.outcome();
  if (kind == StepKind::kDiagnosis && outcome != nullptr && outcome->usable()) {
    // In plain words (diagnosis_words.h), the recommended choice on Enter, the statistics on d.
    const DiagnosisWords words = DiagnosisInPlainWords(outcome->diagnosis, gravity_.gravity_mps2);
    const KeyHint details{"d", show_details_ ? "plain words" : "statistics"};
    if (!words.asks) {
      v.prompt = words.prompt;
      v.keys = WithNavigation({{"Enter", "continue"}, details});
      return;
    }
    const bool ambiguous = !GravityAmbiguityNote(gravity_, outcome->diagnosis.adopted_names()).empty();
    v.prompt = words.prompt + (ambiguous ? " Gravity is the standard value here, so a gravity error looks "
                                           "the same (see the gravity note): with it the report says "
                                           "INCOMPLETE."
                                         : "");
    v.keys = WithNavigation({{"Enter", words.recommended_action}, {"n", "keep basic model"}, details});
    return;
  }
  v.prompt = kind == StepKind::kReport
                 ? "Calibration recorded in the session; press Enter to finish."
                 : "Press Enter to continue.";
  v.keys = WithNavigation({{"Enter", "continue"}, {"r", "retry"}});
}

void WizardEngine::SetDoneView(WizardView& v) const {
  v.screen = WizardScreen::kDone;
  v.finished = true;
  const bool calibrates = std::any_of(procedure_.steps.begin(), procedure_.steps.end(),
                                      [](const ProcedureStep& s) { return s.kind == StepKind::kReport; });
  if (quit_) {
    v.prompt = fmt::format("Saved. Everything accepted is in session {}; run the wizard on it again "
                           "to resume.", options_.session_name);
    return;
  }
  v.prompt = calibrates ? "Calibration complete." : "Procedure complete: every step is recorded.";
  // The verdict and the headline numbers of this run's report (final_summary.h).
  if (const FinalSummary* summary = steps_.final_summary()) {
    v.verdict = std::string(VerdictToString(summary->verdict));
    // The verdict is the summary's first line; the prompt does not say it again.
    if (resumed_ && !progressed_) v.prompt = "Calibration complete (in an earlier run): nothing left to do.";
    v.lines = summary->lines;
    // The flags this run did not use, and what would (a refit), before the summary.
    if (resumed_ && !progressed_) v.lines.insert(v.lines.begin(), options_.notes.begin(), options_.notes.end());
  }
}

void WizardEngine::SetRecordView(WizardView& v) const {
  v.screen = WizardScreen::kRecording;
  v.keys = {{"s", "skip"}, {"b", "back"}, {"q", "save and quit"}};
  const RecordStepWriter& record = acq_.record();
  const RecordView r = record.View();
  v.progress = std::clamp(r.elapsed_s / r.duration_s, 0.0, 1.0);
  const std::string clock = fmt::format("{} of {}", FormatClock(r.elapsed_s), FormatClock(r.duration_s));
  if (acq_.record_settling()) {
    v.prompt = fmt::format("Recording the {} with {}; letting the sensor settle", step().title,
                           step().pose_name);
  } else if (record.resuming()) {
    const std::string gap = r.gaps > record.resumed_from().num_gaps
                                ? fmt::format("gap of {:.0f} s", r.gaps_s - record.resumed_from().gaps_s)
                                : "waiting for the first sample";
    v.prompt = fmt::format("Resuming the {}: {} recorded, {}; recording {}", step().title,
                           FormatLongDuration(record.resumed_from().recorded_s()), gap, clock);
  } else {
    v.prompt = fmt::format("Recording the {} with {}; {}", step().title, step().pose_name, clock);
  }
  v.stability_text = r.bumps == 0 ? "still"
                                  : fmt::format("moved {} time{} (last {}); the record goes on",
                                                r.bumps, r.bumps == 1 ? "" : "s", r.last_bump);
  v.record = r;
}

void WizardEngine::SetCaptureView(WizardView& v) const {
  v.screen = phase_ == Phase::kProblem ? WizardScreen::kError : WizardScreen::kCapturing;
  v.keys = {{"r", "retry"}, {"s", "skip"}, {"b", "back"}, {"q", "save and quit"}};
  if (phase_ == Phase::kProblem) {
    v.prompt = "The capture was not accepted.";
    v.detail = detail_;
    v.keys.insert(v.keys.begin(), KeyHint{"Enter", "try again"});
    return;
  }
  const CaptureSnapshot snap = acq_.capture_snapshot();
  const bool turntable = step().kind == StepKind::kTurntable;
  const CaptureMessage said = DescribeCapture(snap, turntable);
  const bool capturing = snap.state == CaptureState::kCapturing;
  // Time: the capture's seconds left once it captures, the give-up's countdown (sample time,
  // as the capture engine counts it), and the session's estimate.
  v.capture_left_s = capturing ? step().duration_s * (1.0 - snap.progress) : kNaN;
  v.give_up_in_s = std::max(step().timeout_s - snap.elapsed_s, 0.0);
  v.session_left_s = (capturing ? v.capture_left_s : step().duration_s) + SessionLeftS(true);
  v.time_text = CaptureTimeText(step().duration_s, v.capture_left_s, v.give_up_in_s, v.session_left_s);
  v.prompt = fmt::format("{} {} (attempt {}): {}", CaptureStateToString(snap.state), step().pose_name,
                         std::max(1, snap.attempts),
                         capturing ? fmt::format("{:.0f} %, {:.0f} s left; {}", snap.progress * 100.0,
                                                 std::round(v.capture_left_s), said.text)
                                   : said.text);
  v.progress = snap.progress;
  v.waiting = said.waiting;
  v.detail = said.detail;
  if (!turntable) v.stability = snap.stability.WorstRatio();
  v.stability_text = capturing ? (turntable ? "turning steadily" : "still") : said.text;
}

}  // namespace accelcal
