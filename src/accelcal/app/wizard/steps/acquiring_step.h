// What the steps that take readings from the sensor (level, static, turntable, record) share:
// the noise floor measured first when the run has none (noise_floor_step.h), the placement asked
// (Enter when the sensor is in place; on the virtual bench this places it), the capture engine
// run (acquire/capture_engine: settling, stillness, orientation, turntable checks) and what a
// capture that ended unaccepted says and offers (Enter tries again). Each kind adds its own
// phases (the turntable's radius and speed, the leveling's reversal, the record running), its
// placement's words, and what it does with an accepted capture.
#pragma once

#include "accelcal/acquire/capture_engine/capture_engine.h"
#include "accelcal/app/wizard/capture_messages.h"
#include "accelcal/app/wizard/step_controller.h"
#include "accelcal/app/wizard/time_estimate.h"
#include "accelcal/app/wizard/wizard_session.h"
#include "accelcal/session/procedure.h"

namespace accelcal {

class AcquiringStep : public StepController {
 public:
  // Borrows both: they outlive the controller.
  AcquiringStep(const ProcedureStep& step, WizardSession& session) : step_(step), session_(session) {}

  void Enter() override { EnterPlace(); }
  void Handle(const Intent& intent) override;
  bool Acquiring() const override;
  void OnAcquisition(AcquisitionEvent event) override;
  void OnSourceEnded() override {
    phase_ = Phase::kProblem;
    ++refusals_in_row_;  // nothing more will come: trying again and again ends too
  }
  void Halt() override { session_.acq.Stop(); }
  bool BackWithin() override;
  bool AtStart() const override;
  void KeepAfterSkipDeclined() override;
  void SetHeader(WizardView& v) const override;
  void SetView(WizardView& v) const override;
  double WaitingCaptureS(bool on_screen) const override;

 protected:
  enum class Phase {
    kNoiseFloor,  // the noise floor's step runs first (asked or measuring)
    kPlace,       // asking to place the sensor
    kCapture,     // the capture engine runs
    kProblem,     // a capture was rejected or timed out, a record stopped, the source ended
    kOwn,         // a phase of the kind's own
  };

  // The noise floor first when the run has none; else the placement.
  void EnterPlace();
  // The operator says the sensor is in place: the kind's acquisition begins (the noise floor
  // first when the run has none).
  void Begin();
  void StartCaptureEngine();
  // A capture of the step accepted: recorded (before the wizard moves on), confirmed with its
  // figures on the next screen, and its end marked on the session's clock.
  void KeepCapture(const Capture& capture);
  // The capture's label: the pose's name, else the step's title.
  CaptureRequest BaseRequest() const;

  // ---- what a kind may change
  // Places the sensor (on the virtual bench; a real bench has the technician do it), then
  // starts the capture engine.
  virtual void BeginCapture();
  virtual void PlaceOnBench();
  virtual CaptureRequest MakeRequest() const;
  // Leveling measures the same pose twice: it checks no duplicate.
  virtual bool ChecksDuplicates() const { return true; }
  virtual void OnCaptureAccepted(Capture capture) = 0;
  // What the screen says of a capture that ended unaccepted (words, and the figures apart), and
  // the hint under it.
  virtual CaptureMessage RejectedMessage() const;
  virtual std::string RejectedHint() const;
  // Enter after a problem, before the acquisition begins again.
  virtual void BeforeRetry() {}
  // b while acquiring or after a problem.
  virtual void BackFromCapture() { EnterPlace(); }
  // The turntable's capture screen speaks of turning, not stillness.
  virtual bool Turning() const { return false; }
  // The capture's length, s: the step's own; a capture the plan sizes, the plan's (bench_plan.h).
  virtual double CaptureS() const { return step_.duration_s; }
  // The capture's request with the plan's stop rule (a kept capture's kinds call it).
  CaptureRequest Planned(CaptureRequest request) const;
  // The phases of the kind's own (phase_ == kOwn): keys, view.
  virtual void HandleOwn(const Intent& intent);
  virtual void SetOwnView(WizardView& /*v*/) const {}
  virtual void SetPlaceView(WizardView& v) const = 0;

  const ProcedureStep& step_;
  WizardSession& session_;
  Phase phase_ = Phase::kPlace;
  double accepted_elapsed_s_ = kNaN;  // the capture engine's sample time at the last acceptance

 private:
  // Captures of the step refused in a row before Enter saves and quits instead of trying the
  // same again (a script or a person answering Enter would otherwise go round for ever).
  static constexpr int kRefusalsBeforeLeaving = 3;

  void OnCaptureRejected();
  std::string ProblemToCheck() const;
  void SetCaptureView(WizardView& v) const;

  int refusals_in_row_ = 0;  // since the placement was asked or a capture accepted
};

// A step whose sensor is placed on the prism by hand (a static pose, a record): placing it and
// letting go, then the step's own length, s (time_estimate.h).
double PlacedStepEstimateS(const ProcedureStep& step, const TimeAllowances& allowances);

}  // namespace accelcal
