// What the steps of one wizard session share, owned by the engine (wizard_engine.h) and lent to
// each step's controller (step_controller.h): the procedure, the source, the session model (every
// write goes through to the journal) and the options; the session's gravity, noise floor, clock
// and acquisition; the poses captured and the next capture's id; the calibration steps (the
// pipeline's outcome, shared by the fit, the diagnosis and the report); what the screen says;
// and the sequence of steps, which only the engine moves.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/acquire/capture_engine/orientation_check.h"
#include "accelcal/acquire/source/sample_source.h"
#include "accelcal/app/wizard/bench_plan.h"
#include "accelcal/app/wizard/calibration_steps.h"
#include "accelcal/app/wizard/session_clock.h"
#include "accelcal/app/wizard/session_model.h"
#include "accelcal/app/wizard/step_acquisition.h"
#include "accelcal/app/wizard/steps/noise_floor_step.h"
#include "accelcal/app/wizard/wizard_options.h"
#include "accelcal/base/gravity.h"
#include "accelcal/session/procedure.h"

namespace accelcal {

// The engine as the steps see it: the moves from one step to another, the way back, the redo.
class StepSequence {
 public:
  virtual ~StepSequence() = default;
  // The current step is done: `outcome` is recorded in the journal, and the wizard goes on at
  // the next step not recorded.
  virtual void FinishStep(const std::string& outcome) = 0;
  // A capture was recorded: on to the first step without one (a capture left out by a lowered
  // noise floor comes before the next new one).
  virtual void ContinueFromFirstOpenStep() = 0;
  // The current step from its start (r on a result; a skip declined at one of its questions).
  virtual void RestartStep() = 0;
  virtual void AskSkip() = 0;  // s: asks before the step is skipped
  virtual void GoBack() = 0;   // b: to an earlier capture step, when the step goes no further back
  // What q does, asked by a step at a dead end: everything accepted is saved, the wizard ends
  // and the session resumes at this step.
  virtual void SaveAndLeave() = 0;
  // The accepted capture of step `step_id` taken again at once, as b would offer it (the new
  // capture replaces it once accepted; b or s keeps it); the wizard then goes on from the first
  // step not recorded.
  virtual void RetakeStep(const std::string& step_id) = 0;
  // Records `capture`, accepted at the current step (in a redo, superseding the capture taken
  // again), before the wizard moves on.
  virtual void RecordCapture(const Capture& capture) = 0;
  // In a redo, the id of the capture it would replace; 0 when none runs.
  virtual int ReplacedCaptureId() const = 0;
  // The estimated time of the steps not recorded, from the current one (from the next one once
  // `current_started`), s.
  virtual double SessionLeftS(bool current_started) const = 0;
};

// What the screen says beside the step's own view, whoever said it (a step, the engine).
struct ScreenMessages {
  std::string problem;  // what failed, in words
  std::string hint;     // what to do about it
  std::string detail;   // the figures behind `problem` (a capture that ended unaccepted)
  std::string notice;   // the last accepted capture, confirmed until the next key
};

struct WizardSession {
  // Borrows everything: the engine owns it and outlives the session's parts.
  WizardSession(const Procedure& procedure, SampleSource& source, SessionModel& model,
                const WizardOptions& options, WizardOutputs* outputs, StepSequence& sequence);

  // The rough model's "up" of a capture (unit, platform frame).
  Eigen::Vector3d MeasuredUp(const Capture& capture) const;

  const Procedure& procedure;
  SampleSource& source;
  SessionModel& model;
  const WizardOptions& options;
  StepSequence& sequence;
  ScreenMessages screen;
  GravitySpec gravity;      // the session's (the welcome's answer), for the checks and the fit
  CalibrationSteps steps;   // the fit, the diagnosis, the report, the analyses
  SessionClock clock;       // every sample on one clock across resumes
  StepAcquisition acq;      // the noise floor, the capture or the record being acquired
  NoiseFloorStep noise_floor;
  BenchPlan bench_plan;     // each capture's length for the procedure's target (bench_plan.h)
  std::vector<CapturedPose> captured;  // the static poses of the session still used
  int next_capture_id = 1;
  bool adopt_effects = true;  // the diagnosis's choice (Enter adopts, n keeps the base model)
  bool progressed = false;    // this run has recorded a step or a capture
  Eigen::Vector3d live_counts = Eigen::Vector3d::Constant(kNaN);  // the last chunk's mean
};

}  // namespace accelcal
