#include "accelcal/session/procedure_plan.h"

#include <algorithm>
#include <cmath>

#include "accelcal/session/step_kind.h"

namespace accelcal {
namespace {

// A parameter whose target the references alone exceed is planned to within this much of what the
// references allow: U <= (1 + kNearFloor) k u_B.
constexpr double kNearFloor = 0.10;

// Near the references' floor (see PlanSession): every capture at `factor` times its step's length
// (at least its minimum, at most its maximum).
std::vector<double> Scaled(const std::vector<PlannedCapture>& captures, const std::vector<double>& fixed,
                           double factor) {
  std::vector<double> out(fixed.size());
  for (size_t i = 0; i < fixed.size(); ++i)
    out[i] = std::clamp(factor * fixed[i], captures[i].min_capture_s, std::max(captures[i].max_capture_s, captures[i].min_capture_s));
  return out;
}

// Every parameter within its target, or, where the references alone exceed the target, within
// kNearFloor of the fixed plan's floor k u_B or within the fixed plan's own U.
bool MeetsNearFloor(const std::vector<PlannedParameter>& at, const std::vector<PlannedParameter>& fixed, double k) {
  for (size_t j = 0; j < at.size(); ++j) {
    const PlannedParameter& p = at[j];
    if (!std::isfinite(p.predicted_expanded)) return false;
    const double floor_u = std::max((1.0 + kNearFloor) * k * fixed[j].type_b, fixed[j].predicted_expanded);
    const double limit = fixed[j].reachable ? p.target_expanded : floor_u;
    if (std::isfinite(limit) && p.predicted_expanded > limit) return false;
  }
  return true;
}

// Its mounting: the axes on the radius and up ("+x/+z"); a new mounting is paid once.
std::string MountingOf(const ProcedureStep& step) {
  return std::string(SensorAxisToString(step.radial_axis)) + "/" + std::string(SensorAxisToString(step.up_axis));
}

PlannedCapture PlannedCaptureOf(const ProcedureStep& step, const ProcedureTarget& target,
                                double gravity_mps2) {
  PlannedCapture c;
  c.id = step.id;
  c.handling_s = target.pose_handling_s;
  c.optional = !step.required;
  c.max_capture_s = std::max(target.max_capture_s, kMinStaticCaptureS);
  if (InfoOf(step.kind).acquires == StepAcquires::kTurntableCapture) {
    c.kind = CaptureKind::kTurntable;
    c.radius_m = step.radius_m;
    c.rpm = step.rpm;
    c.specific_force_mps2 =
        PlannedCapture::TurntableForce(step.radial_axis, step.up_axis, step.radius_m, step.rpm, gravity_mps2);
    c.mounting = MountingOf(step);
    c.mounting_s = target.mounting_s;
    c.settle_s = kPlannedTurntableSettleS;
    c.min_capture_s = step.rpm > 0.0 ? kMinTurntableRevolutions * 60.0 / step.rpm : kMinStaticCaptureS;
    c.max_capture_s = std::max(c.max_capture_s, c.min_capture_s);
  } else {
    c.kind = CaptureKind::kStatic;
    c.specific_force_mps2 = PlannedCapture::StaticForce(step.up, gravity_mps2);
    c.settle_s = kPlannedStaticSettleS;
    c.min_capture_s = kMinStaticCaptureS;
  }
  return c;
}

bool IsPlannedCaptureStep(const ProcedureStep& step) {
  const StepAcquires a = InfoOf(step.kind).acquires;
  return a == StepAcquires::kStaticCapture || a == StepAcquires::kTurntableCapture;
}

}  // namespace

std::vector<PlannedCapture> PlannedCapturesOf(const Procedure& procedure, double gravity_mps2, double fixed_s) {
  std::vector<PlannedCapture> out;
  for (const ProcedureStep& step : procedure.steps) {
    if (!IsPlannedCaptureStep(step)) continue;
    PlannedCapture c = PlannedCaptureOf(step, procedure.target, gravity_mps2);
    if (fixed_s > 0.0) c.min_capture_s = c.max_capture_s = fixed_s;
    out.push_back(std::move(c));
  }
  return out;
}

PlannedSensor PlannedSensorOf(const Procedure& procedure, const std::optional<Eigen::Vector3d>& noise_counts,
                              double rate_hz) {
  PlannedSensor s;
  s.nominal = procedure.nominal;
  s.rate_hz = rate_hz > 0.0 ? rate_hz : 100.0;
  if (noise_counts && noise_counts->allFinite())
    s.noise_counts = *noise_counts;
  else if (procedure.expected_noise_counts.allFinite())
    s.noise_counts = procedure.expected_noise_counts;
  else
    s.noise_counts = Eigen::Vector3d::Ones();
  return s;
}

const PlannedLength* SessionPlan::For(const std::string& step_id) const {
  if (!planned) return nullptr;
  for (const PlannedLength& l : plan.captures)
    if (l.id == step_id) return l.taken ? &l : nullptr;
  return nullptr;
}

bool SessionPlan::LeftOut(const std::string& step_id) const {
  if (!planned) return false;
  return std::find(plan.buy_nothing.begin(), plan.buy_nothing.end(), step_id) != plan.buy_nothing.end();
}

SessionPlan PlanSession(const Procedure& procedure, const std::optional<Eigen::Vector3d>& noise_counts,
                        double rate_hz, double gravity_mps2, const ReferenceUncertainties& references,
                        double fixed_duration_s) {
  SessionPlan out;
  out.sensor = PlannedSensorOf(procedure, noise_counts, rate_hz);
  PlanOptions options;
  options.gravity_mps2 = gravity_mps2;
  options.references = references;
  options.min_captures = procedure.limits.min_captures;
  const UncertaintyTarget target = ToUncertaintyTarget(procedure.target, procedure.nominal);

  const std::vector<PlannedCapture> captures = PlannedCapturesOf(procedure, gravity_mps2);
  std::vector<double> fixed_lengths;
  for (const ProcedureStep& step : procedure.steps)
    if (IsPlannedCaptureStep(step)) fixed_lengths.push_back(fixed_duration_s > 0.0 ? fixed_duration_s : step.duration_s);
  out.fixed = PlanOfLengths(captures, fixed_lengths, out.sensor, target, options);
  out.planned = procedure.target.Any() && fixed_duration_s <= 0.0;
  if (!out.planned) {
    out.plan = out.fixed;
    return out;
  }
  out.plan = PlanCaptures(captures, out.sensor, target, options);
  for (const PlannedParameter& p : out.fixed.parameters)
    if (!p.reachable) out.beyond_references.push_back(std::string(ParameterName(p.index)));
  if (out.plan.feasible || out.beyond_references.empty()) return out;
  // A target the reference quantities alone exceed is bought by no capture length. Their type-B
  // part depends on the captures' relative weights (a turntable run weighed less leaves the
  // radius's error more say), so the captures keep the fixed plan's proportions and are all
  // shortened together (type B unchanged, type A up) while every parameter stays within its
  // target or within kNearFloor of what the references allow.
  double lo = 0.0, hi = 0.0;
  for (size_t i = 0; i < captures.size(); ++i) hi = std::max(hi, captures[i].max_capture_s / fixed_lengths[i]);
  if (!MeetsNearFloor(PredictUncertainty(captures, Scaled(captures, fixed_lengths, hi), out.sensor, target, options),
                      out.fixed.parameters, options.coverage_factor))
    return out;  // not even at the longest: PlanCaptures' answer (and its message) stands
  for (int step = 0; step < 30; ++step) {
    const double mid = 0.5 * (lo + hi);
    const bool meets = MeetsNearFloor(PredictUncertainty(captures, Scaled(captures, fixed_lengths, mid), out.sensor,
                                                         target, options),
                                      out.fixed.parameters, options.coverage_factor);
    (meets ? hi : lo) = mid;
  }
  out.plan = PlanOfLengths(captures, Scaled(captures, fixed_lengths, hi), out.sensor, target, options);
  out.plan.feasible = true;  // within the targets the bench can reach, near the others' floor
  out.plan.message.clear();
  return out;
}

bool NoiseDiffers(const Eigen::Vector3d& assumed_counts, const Eigen::Vector3d& measured_counts) {
  if (!assumed_counts.allFinite() || !measured_counts.allFinite()) return false;
  const Eigen::Vector3d ratio = measured_counts.cwiseQuotient(assumed_counts.cwiseMax(1e-9));
  return ratio.maxCoeff() > 1.2 || ratio.minCoeff() < 1.0 / 1.2;
}

}  // namespace accelcal
