// A turntable run (kind "turntable"): the radius and the speed asked (a value goes to the field
// its unit names; the plan is checked against the accelerometer's range before the table turns),
// the sensor mounted, the run captured (a wrong mounting or a tilted turntable refused with what
// to do). The accepted capture is kept for the fit with the radius, speed, tilt and the swing
// removed recorded beside it; taken again on the way back (a redo), at the radius and speed it
// was taken with.
#include <cmath>

#include <fmt/core.h>

#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/app/wizard/quantity_input.h"
#include "accelcal/app/wizard/resume_summary.h"
#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/app/wizard/steps/acquiring_step.h"
#include "accelcal/session/session_inputs.h"

namespace accelcal {
namespace {

std::string SwingTriadText(const Eigen::Vector3d& v) {
  return fmt::format("{:.6g} {:.6g} {:.6g}", v.x(), v.y(), v.z());
}

class TurntableStep final : public AcquiringStep {
 public:
  using AcquiringStep::AcquiringStep;

  void Enter() override {
    radius_m_ = step_.radius_m;
    rpm_ = step_.rpm;
    input_error_.clear();
    input_note_.clear();
    phase_ = Phase::kOwn;
    asking_radius_ = true;
  }

  void Halt() override {
    AcquiringStep::Halt();
    StopTable();
  }

  bool BackWithin() override {
    if (phase_ != Phase::kOwn) return AcquiringStep::BackWithin();
    if (asking_radius_) return false;
    asking_radius_ = true;  // from the speed to the radius
    return true;
  }

  bool AtStart() const override {
    return (phase_ == Phase::kOwn && asking_radius_) || AcquiringStep::AtStart();
  }

  // A turntable run taken again offers the radius and speed it was taken with.
  void BeginRedo(const Capture& old) override {
    if (!std::isfinite(old.radius_m) || !std::isfinite(old.rpm)) return;
    radius_m_ = old.radius_m;
    rpm_ = old.rpm;
  }

  void SetHeader(WizardView& v) const override {
    AcquiringStep::SetHeader(v);
    v.step_title = StepDisplayTitle(step_);  // the radius and speed tell the runs of a mounting apart
    v.expected_up = SensorAxisVector(step_.up_axis);
  }

  WizardScreen PlaceScreen() const override { return WizardScreen::kMountTurntable; }

 protected:
  void PlaceOnBench() override {
    if (BenchControl* bench = session_.source.bench())
      bench->PlaceTurntable(radius_m_, rpm_, step_.radial_axis, step_.up_axis);
  }

  CaptureRequest MakeRequest() const override {
    CaptureRequest r = BaseRequest();
    r.kind = CaptureKind::kTurntable;
    r.turntable.radius_m = radius_m_;
    r.turntable.rpm = rpm_;
    r.turntable.radial_axis = SensorAxisVector(step_.radial_axis);
    r.turntable.up_axis = SensorAxisVector(step_.up_axis);
    return Planned(r);  // the plan's length in whole revolutions, ended by its stop rule
  }
  double CaptureS() const override { return session_.bench_plan.CaptureS(step_); }

  bool Turning() const override { return true; }

  // Refused for its tilt: the operator levels the turntable before trying again.
  void BeforeRetry() override {
    if (!session_.acq.last_turntable().level && session_.source.bench() != nullptr)
      session_.source.bench()->LevelTurntable();
  }

  void BackFromCapture() override {
    phase_ = Phase::kOwn;
    asking_radius_ = false;
    session_.acq.Stop();
  }

  // The pull toward the outside that does not match the speed and radius entered, in bench words
  // (a table that does not turn; the speed or the radius that the measurement fits); the figures
  // apart.
  CaptureMessage RejectedMessage() const override {
    const TurntableVerdict& v = session_.acq.last_turntable();
    const std::string& reason = session_.acq.reason();
    if (v.consistent || !std::isfinite(v.centripetal_ratio) || reason.rfind("radius looks", 0) == 0 ||
        reason.find("expected from") == std::string::npos)
      return AcquiringStep::RejectedMessage();
    if (v.centripetal_ratio < 0.05)
      return {fmt::format("the table does not seem to turn: no pull toward the outside was measured (at {:g} rpm "
                          "it would be {:.2g} g)",
                          rpm_, v.expected_centripetal_mps2 / session_.gravity.gravity_mps2),
              reason, false};
    const double ratio = std::max(v.centripetal_ratio, 0.0);
    return {fmt::format("the table's pull does not match {:g} rpm at {:g} mm: it fits {:.3g} rpm at that radius, "
                        "or {:.3g} mm at that speed",
                        rpm_, radius_m_ * 1000.0, rpm_ * std::sqrt(ratio), radius_m_ * 1000.0 * ratio),
            reason, false};
  }

  std::string RejectedHint() const override {
    const TurntableVerdict& v = session_.acq.last_turntable();
    if (!v.consistent && std::isfinite(v.centripetal_ratio) && v.centripetal_ratio < 0.05)
      return fmt::format("start the table at {:g} rpm and wait until it turns steadily; Enter tries again", rpm_);
    if (!v.consistent && std::isfinite(v.centripetal_ratio))
      return "measure the radius with the ruler and check the speed on the table (or with a tachometer); "
             "Enter tries again, b re-enters them";
    if (!v.mounted_as_asked && !v.mounting_found.empty())
      return fmt::format("stop the table, mount the sensor {} as asked and start the table again; "
                         "Enter tries again", step_.pose_name);
    return !v.level ? "level the turntable; Enter tries again"
                    : "check the mounting, radius and speed; Enter tries again, b re-enters the values";
  }

  void OnCaptureAccepted(Capture capture) override {
    capture.up_axis = step_.up_axis;
    SessionModel& model = session_.model;
    model.RecordInput(step_.id, turntable_key::kRadiusM, fmt::format("{}", radius_m_));
    model.RecordInput(step_.id, turntable_key::kRpm, fmt::format("{}", rpm_));
    // The swing removed from the samples, so that the raw readings can be rebuilt.
    const TurntableVerdict& v = session_.acq.last_turntable();
    model.RecordInput(step_.id, turntable_key::kTableTiltDeg, fmt::format("{:.4f}", v.tilt_deg));
    model.RecordInput(step_.id, turntable_key::kSwingRemovedCounts,
                      fmt::format("t0 {:.6f} w {:.9g} cos {} sin {}", v.swing.t0_s, v.swing.w_rad_per_s,
                                  SwingTriadText(v.swing.cos_counts), SwingTriadText(v.swing.sin_counts)));
    KeepCapture(capture);
    session_.next_capture_id = capture.id + 1;
    StopTable();
    session_.sequence.ContinueFromFirstOpenStep();
  }

  // A value goes to the field its unit names, wherever the cursor is: "300 rpm" typed at the
  // radius corrects the speed (the technician read "lower the speed" and typed a speed). The
  // cursor stays; a note says what was taken. Blank text is empty: the field's default.
  void HandleOwn(const Intent& intent) override {
    if (intent.kind == IntentKind::kSkip) return session_.sequence.AskSkip();
    if (intent.kind == IntentKind::kBack) {
      input_error_.clear();  // the refusal was about the field left
      input_note_.clear();
      return session_.sequence.GoBack();
    }
    if (intent.kind != IntentKind::kAccept && intent.kind != IntentKind::kSubmitText) return;
    const bool radius = asking_radius_;
    const std::string text = intent.kind == IntentKind::kSubmitText && !IsBlank(intent.text) ? intent.text : "";
    input_note_.clear();
    const TurntableField unit_field = FieldOfUnit(text);
    if (unit_field != TurntableField::kNone && (unit_field == TurntableField::kRadius) != radius)
      return CorrectOtherField(text, unit_field == TurntableField::kRadius);
    const double fallback = radius ? radius_m_ : rpm_;
    const QuantityResult q =
        text.empty() ? QuantityResult{fallback, ""} : (radius ? ParseRadius(text) : ParseRpm(text));
    if (!q.ok()) {
      input_error_ = q.error;
      return;
    }
    input_error_.clear();
    if (radius) {
      radius_m_ = q.value;
      asking_radius_ = false;
      return;
    }
    CheckPlanAndPlace(q.value);
  }

  void SetPlaceView(WizardView& v) const override {
    v.screen = WizardScreen::kMountTurntable;
    v.prompt = fmt::format(
        "Stop the table before you touch the sensor. Mount it with {} at {:g} mm from the axis, then "
        "start the table at {:g} rpm and wait for it to settle; press Enter when it turns steadily.",
        step_.pose_name, radius_m_ * 1000.0, rpm_);
    v.keys = WithNavigation({{"Enter", "capture"}});
  }

  void SetOwnView(WizardView& v) const override {
    const bool radius = asking_radius_;
    v.screen = WizardScreen::kInput;
    v.prompt = fmt::format("Turntable run with {}: stop the table before you touch the sensor.", step_.pose_name);
    if (!input_note_.empty()) v.prompt += " " + input_note_;
    v.input = InputRequest{radius ? "radius" : "rpm",
                           radius ? "Radius from the spin axis to the sensor (e.g. 120 mm)"
                                  : "Table speed (e.g. 120 rpm, 2 rps or 2 Hz, 12.57 rad/s)",
                           radius ? fmt::format("{:g} mm", radius_m_ * 1000.0) : fmt::format("{:g} rpm", rpm_),
                           input_error_};
    v.keys = WithNavigation({{"Enter", "accept"}});
  }

 private:
  void StopTable() {
    if (BenchControl* bench = session_.source.bench()) bench->StopTurntable();
  }

  void CorrectOtherField(const std::string& text, bool to_radius) {
    const QuantityResult q = to_radius ? ParseRadius(text) : ParseRpm(text);
    if (!q.ok()) {
      input_error_ = q.error;
      return;
    }
    input_error_.clear();
    (to_radius ? radius_m_ : rpm_) = q.value;
    input_note_ = to_radius ? fmt::format("Radius set to {:g} mm; now the speed.", q.value * 1000.0)
                            : fmt::format("Speed set to {:g} rpm; now the radius.", q.value);
  }

  // The plan (radius_m_ with `rpm`) against the accelerometer's range. A refused speed never
  // becomes the default: the default goes back to the procedure's, and the cursor stays on the
  // speed, where the technician types next (or types a radius there: see above).
  void CheckPlanAndPlace(double rpm) {
    TurntableSetup setup;
    setup.radius_m = radius_m_;
    setup.rpm = rpm;
    setup.radial_axis = SensorAxisVector(step_.radial_axis);
    setup.up_axis = SensorAxisVector(step_.up_axis);
    TurntableStabilityOptions o;
    o.gravity_mps2 = session_.gravity.gravity_mps2;
    const Procedure& p = session_.procedure;
    const std::string why = CheckTurntableAgainstRange(setup, p.range_g, p.nominal, p.adc_range, o);
    if (!why.empty()) {
      input_error_ = why;
      rpm_ = step_.rpm;
      return;
    }
    rpm_ = rpm;
    EnterPlace();
  }

  // kOwn: the radius is asked (asking_radius_), else the speed.
  bool asking_radius_ = true;
  double radius_m_ = kNaN;
  double rpm_ = kNaN;
  std::string input_error_;  // why the last answer was refused
  std::string input_note_;   // what a typed value set in the other field
};

double TurntableEstimateS(const ProcedureStep& step, const TimeAllowances& a) {
  return a.mount_turntable_s + a.settle_s + step.duration_s;
}

// A turntable step whose title is only its mounting (several steps share it) gets "Turntable"
// and its radius ("Turntable x radial, z up at 100 mm").
std::string TurntableDisplayTitle(const ProcedureStep& step) {
  if (step.title != step.pose_name) return step.title;
  std::string title = fmt::format("{} at {:g} mm", step.pose_name, step.radius_m * 1000.0);
  if (std::isfinite(step.rpm)) title += fmt::format(", {:g} rpm", step.rpm);
  return title;
}

// What to type at the run's two questions.
std::string TurntableInputHelp(std::string_view key) {
  if (key == "radius")
    return "Type the distance from the turntable's spin axis to the sensor, with its unit: 120 mm, "
           "12 cm or 0.12 m (a number alone is metres; a decimal comma works: 0,12). A speed typed "
           "here (300 rpm) sets the speed instead. An empty answer takes the value in brackets.";
  if (key == "rpm")
    return "Type the table's speed: 120 (rpm), 120 rpm, 2 rps or 2 Hz, 12.57 rad/s. Before the "
           "table turns the plan is checked against the accelerometer's range; when it is refused, "
           "type a lower speed here, or a radius (5 cm) to correct the radius. An empty answer "
           "takes the value in brackets.";
  return "";
}

}  // namespace

StepControllerKind TurntableStepKind() {
  return {StepKind::kTurntable, &MakeStepController<TurntableStep>, &TurntableEstimateS, &TurntableDisplayTitle,
          &TurntableInputHelp};
}

}  // namespace accelcal
