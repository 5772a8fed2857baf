// The session's capture plan in the wizard (issue 32: the technician's time): each capture's
// length from the procedure's [target] and the sensor's noise (session/procedure_plan.h), the
// stop rule a capture controller gives the capture engine (a sample count fixed before the
// capture starts: calibration/capture_stop_rule.h), what the welcome says of the bench time, and
// the bench time each accepted capture took, recorded for the report.
//
// The plan assumes the procedure's expected noise until the session's noise floor is measured;
// it is made again when the floor differs from what it assumed (NoiseDiffers), and the captures
// not yet taken follow the new plan. A procedure without a [target], or --fixed-duration, keeps
// fixed lengths (each step's own, or the option's).
//
// Units: s, samples, Hz, counts.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/acquire/capture_engine/capture_request.h"
#include "accelcal/session/equipment.h"
#include "accelcal/session/procedure_plan.h"

namespace accelcal {

class SessionModel;
struct WizardSession;

class BenchPlan {
 public:
  // `fixed_duration_s` > 0: every capture that long (the old behaviour, for comparison).
  BenchPlan(const Procedure& procedure, double fixed_duration_s) : procedure_(procedure), fixed_s_(fixed_duration_s) {}

  // Plans (again) when nothing is planned yet, or the session's noise floor, sample rate,
  // gravity or equipment differ from what the plan assumed; records the plan in the journal.
  // `equipment`: the items to plan with instead of the session's (the welcome's: those its
  // question offers, which Enter keeps, before it is answered).
  void Refresh(WizardSession& session, const std::vector<EquipmentItem>* equipment = nullptr);
  const SessionPlan& plan() const { return plan_; }
  bool by_target() const { return plan_.planned; }

  // The capture of `step`: its length (s) and the sample count that ends it; the step's own
  // duration (no count) for a step the plan does not hold.
  double CaptureS(const ProcedureStep& step) const;
  void Apply(const ProcedureStep& step, CaptureRequest* request) const;
  // The give-up of a capture of `step` planned `capture_s` long, counted from the pose's first
  // sample: the procedure's (the step's timeout_s) whenever the capture fits in it.
  static double GiveUpS(const ProcedureStep& step, double capture_s);
  // The session's time left for `step`, whose kind estimates `step_estimate_s` (time_estimate.h):
  // a capture step the plan holds takes the plan's time, as the welcome counted it (its capture
  // length, settling, the pose's handling, and its turntable mounting unless `mounted` says one
  // of its mounting was counted already: each mounting is paid once); 0 for a step the plan
  // leaves out (it is skipped); any other step its kind's estimate.
  double StepLeftS(const ProcedureStep& step, double step_estimate_s, std::set<std::string>* mounted) const;
  // The plan leaves `step` out: an optional capture that buys nothing for this sensor.
  bool LeavesOut(const ProcedureStep& step) const { return fixed_s_ <= 0.0 && plan_.LeftOut(step.id); }

  // The welcome's line: "This plan reaches the procedure's target in about 7 min at the bench
  // (fixed 10 s captures: about 13 min)", or why it cannot and how long it would take.
  std::string WelcomeText() const;
  // The capture screen's words for the bar: "enough data: 62 %" (by the plan) or "" (fixed).
  std::string ProgressWords(double progress) const;

  // An accepted capture of `step`: its bench time (capture, settling, handling) recorded at the
  // step. `elapsed_s`: the capture engine's sample time from its first sample to acceptance.
  void RecordSpent(WizardSession& session, const ProcedureStep& step, const Capture& capture, double elapsed_s);

 private:
  void Record(SessionModel& model) const;
  std::string PlanWords() const;
  double HandlingS(WizardSession& session, const ProcedureStep& step) const;

  const Procedure& procedure_;
  double fixed_s_ = 0.0;
  bool made_ = false;
  SessionPlan plan_;
  Eigen::Vector3d assumed_noise_ = Eigen::Vector3d::Constant(kNaN);
  double assumed_rate_hz_ = kNaN;
  double assumed_gravity_ = kNaN;
  ReferenceUncertainties assumed_refs_;
  double last_capture_end_t_s_ = kNaN;  // session clock, a real bench's handling
};

// The sample rate of `samples` (Hz); NaN with fewer than 2 or no time between them.
double SampleRateHz(const std::vector<Sample>& samples);

}  // namespace accelcal
