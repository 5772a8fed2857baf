// The session's noise floor (noise_floor_guard.h), the short step that measures it: the sensor
// rests for the quiet period before the first step of a run that takes readings from the sensor
// (acquiring_step.h runs it there), the floor is judged, recorded (input "noise_floor" of the
// journal) and shown; on a resume, a floor an earlier run lowered is restored; each static
// capture accepted checks it again (Recheck), lowering it when the capture proves it too high
// and leaving out the captures that fail the lower floor. A source whose readings come in steps
// (MAVLink's SCALED_IMU: 1 mG) as coarse as the floor measured has its resolution said beside
// the floor and recorded (input "resolution"): such a floor is the rounding, not the sensor.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "accelcal/acquire/capture_engine/noise_floor.h"
#include "accelcal/acquire/capture_engine/orientation_check.h"
#include "accelcal/acquire/source/sample_source.h"
#include "accelcal/app/wizard/noise_floor_guard.h"
#include "accelcal/app/wizard/session_model.h"
#include "accelcal/app/wizard/step_acquisition.h"
#include "accelcal/app/wizard/wizard_view.h"
#include "accelcal/session/procedure.h"

namespace accelcal {

struct ScreenMessages;

class NoiseFloorStep {
 public:
  // Borrows everything; `quiet_period_s`: how long the sensor rests, s; `source` (nullable): the
  // source whose resolution is said beside the floor.
  NoiseFloorStep(const Procedure& procedure, SessionModel& model, StepAcquisition& acq,
                 ScreenMessages& screen, double quiet_period_s, const SampleSource* source = nullptr);

  // Reads a floor lowered in an earlier run (the captures were judged again with it).
  void Resume();

  // The floor, once measured in this run; nullopt before.
  const std::optional<NoiseFloor>& floor() const { return guard_.floor(); }
  // "x 1.52  y 1.49  z 1.71 counts (quiet period of 2.0 s, 200 samples)"; empty before.
  std::string Describe() const { return guard_.Describe(); }
  // What the floor's checks said, shown beside the steps that acquire.
  const std::vector<std::string>& lines() const { return lines_; }

  // The step: Ask (the operator is asked to leave the sensor at rest), Measure (Enter: the quiet
  // period runs), then the acquisition's report: OnMeasured (true when the floor is accepted and
  // recorded; refused: asked again with why) or OnSilent (no samples: asked again).
  void Ask() { measuring_ = false; }
  void Measure(double timeout_s);
  bool measuring() const { return measuring_; }
  // Measurements refused (or silent) in a row in this run.
  int refusals_in_row() const { return refusals_in_row_; }
  // The same bench measured again will not do: the floor refused for kRefusedLongestS of the
  // bench's clock (a bench that shakes settles sooner; a sensor noisier than the procedure
  // expects never does), or silent kSilentBeforeLeaving times in a row. Enter then saves and
  // quits (r still measures).
  bool gives_up() const { return gives_up_; }
  static constexpr double kRefusedLongestS = 120.0;
  static constexpr int kSilentBeforeLeaving = 3;
  bool OnMeasured();
  void OnSilent();
  void SetView(WizardView& v) const;
  // What the source's resolution means for the floor measured: empty when the step is unknown
  // or well below the floor on every axis.
  std::string ResolutionLimit() const;

  // `latest`, a static capture just accepted, checks the floor: when it proves it too high the
  // floor is lowered, and the captures judged with the old one judged again; those that fail
  // are left out (their poses taken out of `captured`) and their steps captured again.
  void Recheck(const Capture& latest, std::vector<CapturedPose>& captured);

 private:
  void Refused(const std::string& check, bool silent);

  const Procedure& procedure_;
  SessionModel& model_;
  StepAcquisition& acq_;
  ScreenMessages& screen_;
  double quiet_period_s_;
  const SampleSource* source_;
  NoiseFloorGuard guard_;
  std::optional<NoiseFloor> lowered_;  // a floor lowered by the captures (this run or before)
  std::vector<std::string> lines_;
  bool measuring_ = false;
  int refusals_in_row_ = 0;
  int silent_in_row_ = 0;
  double first_refused_t_s_ = kNaN;  // the bench's clock at the first refusal in a row
  bool gives_up_ = false;
};

}  // namespace accelcal
