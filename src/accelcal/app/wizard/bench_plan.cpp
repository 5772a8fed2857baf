#include "accelcal/app/wizard/bench_plan.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/app/wizard/time_estimate.h"
#include "accelcal/app/wizard/wizard_session.h"
#include "accelcal/calibration/capture_stop_rule.h"
#include "accelcal/session/equipment.h"
#include "accelcal/session/session_inputs.h"

namespace accelcal {
namespace {

// Before the noise floor: a bench's rate is not known yet; the plan's lengths are in seconds,
// its counts are taken at the rate measured by then.
constexpr double kAssumedRateHz = 100.0;

std::string PlannedUText(const std::vector<PlannedParameter>& parameters, bool target) {
  std::string out;
  for (const PlannedParameter& p : parameters)
    out += fmt::format("{}{:.6g}", out.empty() ? "" : " ", target ? p.target_expanded : p.predicted_expanded);
  return out;
}

bool SameOrBothNaN(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

}  // namespace

double SampleRateHz(const std::vector<Sample>& samples) {
  if (samples.size() < 2) return kNaN;
  const double span_s = samples.back().t_s - samples.front().t_s;
  return span_s > 0.0 ? static_cast<double>(samples.size() - 1) / span_s : kNaN;
}

void BenchPlan::Refresh(WizardSession& session, const std::vector<EquipmentItem>* equipment) {
  const std::optional<NoiseFloor>& floor = session.noise_floor.floor();
  const std::optional<Eigen::Vector3d> noise =
      floor ? std::optional<Eigen::Vector3d>(floor->std_counts) : std::nullopt;
  // The rate measured in this run's quiet period, else a resumed session's last capture's.
  double rate_hz = SampleRateHz(session.acq.quiet_samples());
  if (!std::isfinite(rate_hz) && !session.model.captures().empty())
    rate_hz = SampleRateHz(session.model.captures().back().capture.samples);
  if (!std::isfinite(rate_hz)) rate_hz = std::isfinite(assumed_rate_hz_) ? assumed_rate_hz_ : kAssumedRateHz;
  const double gravity = session.gravity.gravity_mps2;
  const Eigen::Vector3d assumed = PlannedSensorOf(procedure_, noise, rate_hz).noise_counts;
  const bool noise_moved = !made_ || NoiseDiffers(assumed_noise_, assumed);
  const bool rate_moved = !made_ || std::abs(rate_hz - assumed_rate_hz_) > 0.02 * assumed_rate_hz_;
  const ReferenceUncertainties references = ToReferenceUncertainties(
      equipment != nullptr ? *equipment : session.steps.equipment(), session.gravity.sigma_mps2);
  const bool references_moved =
      !SameOrBothNaN(references.gravity_mps2, assumed_refs_.gravity_mps2) ||
      !SameOrBothNaN(references.radius_m, assumed_refs_.radius_m) ||
      !SameOrBothNaN(references.rpm_relative, assumed_refs_.rpm_relative) ||
      !SameOrBothNaN(references.table_tilt_rad, assumed_refs_.table_tilt_rad);
  if (made_ && !noise_moved && !rate_moved && !references_moved && SameOrBothNaN(gravity, assumed_gravity_)) return;
  plan_ = PlanSession(procedure_, noise, rate_hz, gravity, references, fixed_s_);
  made_ = true;
  assumed_noise_ = assumed;
  assumed_rate_hz_ = rate_hz;
  assumed_gravity_ = gravity;
  assumed_refs_ = references;
  Record(session.model);
}

void BenchPlan::Record(SessionModel& model) const {
  const CapturePlan& p = plan_.plan;
  model.RecordInput(kBenchPlanStepId, bench_key::kPlannedBy, plan_.planned ? "target" : "fixed");
  model.RecordInput(kBenchPlanStepId, bench_key::kPlannedCaptureS, fmt::format("{:.3f}", p.capture_s));
  model.RecordInput(kBenchPlanStepId, bench_key::kPlannedSettleS, fmt::format("{:.3f}", p.settle_s));
  model.RecordInput(kBenchPlanStepId, bench_key::kPlannedHandlingS, fmt::format("{:.3f}", p.handling_s));
  model.RecordInput(kBenchPlanStepId, bench_key::kPlannedU, PlannedUText(p.parameters, false));
  model.RecordInput(kBenchPlanStepId, bench_key::kTargetU, PlannedUText(p.parameters, true));
}

double BenchPlan::CaptureS(const ProcedureStep& step) const {
  if (fixed_s_ > 0.0) return fixed_s_;
  if (const PlannedLength* l = plan_.For(step.id)) return l->capture_s;
  return step.duration_s;
}

double BenchPlan::StepLeftS(const ProcedureStep& step, double step_estimate_s, std::set<std::string>* mounted) const {
  if (LeavesOut(step)) return 0.0;
  if (fixed_s_ <= 0.0 && plan_.For(step.id) == nullptr) return step_estimate_s;
  const StepAcquires a = InfoOf(step.kind).acquires;
  if (a != StepAcquires::kStaticCapture && a != StepAcquires::kTurntableCapture) return step_estimate_s;
  const ProcedureTarget& t = procedure_.target;
  double left_s = CaptureS(step) + t.pose_handling_s;
  if (a == StepAcquires::kStaticCapture) return left_s + kPlannedStaticSettleS;
  left_s += kPlannedTurntableSettleS;
  const std::string mounting =
      std::string(SensorAxisToString(step.radial_axis)) + "/" + std::string(SensorAxisToString(step.up_axis));
  if (mounted->insert(mounting).second) left_s += t.mounting_s;
  return left_s;
}

void BenchPlan::Apply(const ProcedureStep& step, CaptureRequest* request) const {
  if (fixed_s_ <= 0.0 && plan_.For(step.id) == nullptr) return;  // the step's own duration
  const double capture_s = CaptureS(step);
  const double rate_hz = std::isfinite(assumed_rate_hz_) ? assumed_rate_hz_ : kAssumedRateHz;
  const bool turning = request->kind == CaptureKind::kTurntable && request->turntable.rpm > 0.0;
  const double revolution_s = turning ? 60.0 / request->turntable.rpm : 0.0;
  CaptureStopRule rule;
  if (fixed_s_ > 0.0) {
    rule = CaptureStopRule::For(fixed_s_, rate_hz, fixed_s_, fixed_s_);
  } else {
    // The plan's length, in whole revolutions on the turntable (at most one more than planned).
    const double min_s = std::min(capture_s, turning ? kMinTurntableRevolutions * revolution_s : kMinStaticCaptureS);
    rule = CaptureStopRule::For(capture_s, rate_hz, min_s, capture_s + revolution_s,
                                turning ? request->turntable.rpm : 0.0);
  }
  request->stop_samples = rule.needed_samples;
  request->duration_s = static_cast<double>(rule.needed_samples) / rate_hz;
  request->timeout_s = GiveUpS(step, request->duration_s);
}

double BenchPlan::GiveUpS(const ProcedureStep& step, double capture_s) {
  // The give-up counts from the pose's first sample, and the capture engine checks it only
  // while no capture runs: a capture begun in time runs to its end, however long the plan made
  // it. So the procedure's capture_timeout_s holds for any planned length that fits in it; a
  // capture as long (a noisy sensor's, up to max_capture_s) keeps the step's slack after it.
  if (capture_s < step.timeout_s) return step.timeout_s;
  return capture_s + std::max(step.timeout_s - step.duration_s, 1.0);
}

std::string BenchPlan::WelcomeText() const {
  const CapturePlan& p = plan_.plan;
  if (!made_ || p.captures.empty() || (!plan_.planned && fixed_s_ <= 0.0)) return "";
  std::string beyond;
  if (!plan_.beyond_references.empty()) {
    std::string names;
    for (const std::string& n : plan_.beyond_references)
      if (names.find(n) == std::string::npos) names += (names.empty() ? "" : ", ") + n;
    beyond = fmt::format(" No capture length reaches the target on {}: the uncertainty of the local gravity "
                         "and the equipment (ruler, turntable, level) alone exceeds it; the plan takes these "
                         "to within 10 % of what the equipment allows (or the fixed plan's U), the captures in the fixed plan's proportions.", names);
  }
  return PlanWords() + beyond;
}

std::string BenchPlan::PlanWords() const {
  const CapturePlan& p = plan_.plan;
  const std::string fixed = fmt::format("{} s captures", plan_.fixed.captures.empty() ? 0.0 : plan_.fixed.captures.front().capture_s);
  if (!plan_.planned)
    return fmt::format("The captures take about {} at the bench ({}, handling included).", FormatEstimate(p.TotalS()), fixed);
  if (p.feasible)
    return fmt::format("This plan reaches the procedure's target in {} at the bench, handling included "
                       "(fixed {}: {}).", FormatEstimate(p.TotalS()), fixed, FormatEstimate(plan_.fixed.TotalS()));
  if (std::isfinite(p.unbounded_total_s))
    return fmt::format("With this sensor's noise the target needs captures longer than the procedure allows: "
                       "{} at the bench with no limit; the plan takes the longest allowed ({}).",
                       FormatEstimate(p.unbounded_total_s), FormatEstimate(p.TotalS()));
  return fmt::format("The target cannot be reached on this bench ({}); the plan takes the longest captures "
                     "allowed ({}).", p.message, FormatEstimate(p.TotalS()));
}

std::string BenchPlan::ProgressWords(double progress) const {
  if (!plan_.planned) return "";
  return progress >= 1.0 ? "enough data: move on" : fmt::format("enough data: {:.0f} %", 100.0 * progress);
}

double BenchPlan::HandlingS(WizardSession& session, const ProcedureStep& step) const {
  const ProcedureTarget& t = procedure_.target;
  double handling = t.pose_handling_s;
  if (InfoOf(step.kind).acquires == StepAcquires::kTurntableCapture) {
    // The mounting is paid at its first capture in the session.
    bool mounted_before = false;
    for (const ProcedureStep& other : procedure_.steps) {
      if (&other == &step) break;
      if (InfoOf(other.kind).acquires == StepAcquires::kTurntableCapture && other.radial_axis == step.radial_axis &&
          other.up_axis == step.up_axis && session.model.inputs().count(other.id) &&
          session.model.inputs().at(other.id).count(bench_key::kCaptureS))
        mounted_before = true;
    }
    if (!mounted_before) handling += t.mounting_s;
  }
  return handling;
}

void BenchPlan::RecordSpent(WizardSession& session, const ProcedureStep& step, const Capture& capture,
                            double elapsed_s) {
  const CaptureStats& st = capture.stats();
  const double capture_s =
      st.n > 1 ? (st.t_last_s - st.t_first_s) * static_cast<double>(st.n) / static_cast<double>(st.n - 1) : 0.0;
  const double settle_s = std::isfinite(elapsed_s) ? std::max(elapsed_s - capture_s, 0.0) : 0.0;
  // The virtual bench places the sensor at once: its handling is the procedure's model. A real
  // bench's is its clock: from the previous capture's end to this one's start.
  double handling_s = HandlingS(session, step);
  if (session.source.bench() == nullptr && std::isfinite(last_capture_end_t_s_))
    handling_s = std::max(st.t_first_s - settle_s - last_capture_end_t_s_, 0.0);
  SessionModel& model = session.model;
  model.RecordInput(step.id, bench_key::kCaptureS, fmt::format("{:.3f}", capture_s));
  model.RecordInput(step.id, bench_key::kSettleS, fmt::format("{:.3f}", settle_s));
  model.RecordInput(step.id, bench_key::kHandlingS, fmt::format("{:.3f}", handling_s));
  last_capture_end_t_s_ = st.t_last_s;
}

}  // namespace accelcal
