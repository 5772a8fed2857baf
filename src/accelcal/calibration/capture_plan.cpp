#include "accelcal/calibration/capture_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include <Eigen/Cholesky>

#include "accelcal/calibration/fit/least_squares.h"
#include "accelcal/calibration/fit/residual_model.h"

namespace accelcal {
namespace {

constexpr double kPlanQuantizationFloorCounts2 = 1.0 / 12.0;  // as the fit floors it
// A capture's length when its maximum is lifted (the "how long would it take" question).
constexpr double kUnboundedCaptureS = 3600.0;

// The capture as the fit would see it after `length_s` of samples from the nominal sensor.
FitCapture AsFitCapture(const PlannedCapture& planned, const PlannedSensor& sensor, double length_s) {
  FitCapture c;
  c.kind = planned.kind;
  c.radius_m = planned.radius_m;
  c.rpm = planned.rpm;
  c.mean_counts = sensor.nominal.Raw(planned.specific_force_mps2);
  c.n_samples = std::max(1L, std::lround(sensor.rate_hz * length_s));
  Eigen::Matrix3d per_sample = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 3; ++a)
    per_sample(a, a) = std::max(sensor.noise_counts(a) * sensor.noise_counts(a), kPlanQuantizationFloorCounts2);
  c.mean_cov_counts2 = per_sample / static_cast<double>(c.n_samples);
  return c;
}

// A_i: the information one second of capture i adds (J_i^T J_i / sigma_i^2 at rate samples).
Eigen::MatrixXd InformationPerSecond(const PlannedCapture& planned, const PlannedSensor& sensor,
                                     double gravity_mps2) {
  const BaseResidualModel model;
  const FitCapture c = AsFitCapture(planned, sensor, 1.0);
  const Eigen::VectorXd p = sensor.nominal.ToVector();
  Eigen::VectorXd grad(kNumBaseParameters);
  Eigen::Vector3d grad_raw;
  model.Residual(p, c, gravity_mps2, &grad, &grad_raw);
  Eigen::Matrix3d per_sample = c.mean_cov_counts2 * static_cast<double>(c.n_samples);
  const double var_per_sample = grad_raw.dot(per_sample * grad_raw);
  return grad * grad.transpose() * (sensor.rate_hz / var_per_sample);
}

std::vector<Eigen::MatrixXd> InformationPerSecond(const std::vector<PlannedCapture>& captures,
                                                  const PlannedSensor& sensor, double gravity_mps2) {
  std::vector<Eigen::MatrixXd> a;
  a.reserve(captures.size());
  for (const PlannedCapture& c : captures) a.push_back(InformationPerSecond(c, sensor, gravity_mps2));
  return a;
}

// (sum_i d_i A_i)^-1; empty when not positive definite (the captures leave a combination free).
Eigen::MatrixXd InverseInformation(const std::vector<Eigen::MatrixXd>& a, const std::vector<double>& d) {
  Eigen::MatrixXd info = Eigen::MatrixXd::Zero(kNumBaseParameters, kNumBaseParameters);
  for (size_t i = 0; i < a.size(); ++i)
    if (d[i] > 0.0) info += d[i] * a[i];
  // Equilibrate before deciding: the parameters' units differ by orders of magnitude.
  const Eigen::VectorXd s = info.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd scaled = s.asDiagonal() * info * s.asDiagonal();
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(scaled);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive() ||
      ldlt.vectorD().minCoeff() < 1e-12 * ldlt.vectorD().maxCoeff())
    return {};
  const Eigen::MatrixXd inv = ldlt.solve(Eigen::MatrixXd::Identity(kNumBaseParameters, kNumBaseParameters));
  return s.asDiagonal() * inv * s.asDiagonal();
}

// The type-B part of each parameter's u_c, from the budget of the fit predicted for `lengths`.
Eigen::VectorXd TypeBParts(const std::vector<PlannedCapture>& captures, const std::vector<double>& lengths,
                           const PlannedSensor& sensor, const Eigen::MatrixXd& covariance,
                           const PlanOptions& options) {
  Eigen::VectorXd parts = Eigen::VectorXd::Zero(kNumBaseParameters);
  std::vector<FitCapture> taken;
  for (size_t i = 0; i < captures.size(); ++i)
    if (lengths[i] > 0.0) taken.push_back(AsFitCapture(captures[i], sensor, lengths[i]));
  FitSummary fit;
  fit.termination = FitTermination::kConverged;
  fit.parameters = sensor.nominal.ToVector();
  fit.covariance = covariance;
  fit.uncertainty = covariance.diagonal().cwiseSqrt();
  fit.num_captures = static_cast<int>(taken.size());
  fit.dof = fit.num_captures - kNumBaseParameters;
  const UncertaintyBudget budget =
      MakeUncertaintyBudget(BaseResidualModel{}, taken, fit, options.gravity_mps2, options.references);
  for (const ParameterBudget& pb : budget.parameters) {
    double b2 = 0.0;
    for (const BudgetContribution& c : pb.contributions)
      if (c.type == 'B' && std::isfinite(c.contribution)) b2 += c.contribution * c.contribution;
    parts(pb.index) = std::sqrt(b2);
  }
  return parts;
}

// The allowance of u_A^2 per parameter: (margin U / k)^2 - type B^2; +inf: no target; < 0: the
// type-B part alone exceeds it.
Eigen::VectorXd Allowances(const UncertaintyTarget& target, const SensorModel& nominal,
                           const Eigen::VectorXd& type_b, const PlanOptions& options) {
  Eigen::VectorXd allow(kNumBaseParameters);
  for (int j = 0; j < kNumBaseParameters; ++j) {
    const double u = target.ForParameter(j, nominal);
    if (!std::isfinite(u)) {
      allow(j) = std::numeric_limits<double>::infinity();
      continue;
    }
    const double wanted = options.margin * u / options.coverage_factor;
    allow(j) = wanted * wanted - type_b(j) * type_b(j);
  }
  return allow;
}

struct Allocation {
  bool met = false;
  std::vector<double> lengths;  // 0 for a capture not taken
};

// The least total capture time over the taken captures meeting every allowance: start each at
// its minimum, then give a step to the capture that lowers the shortfall most per second.
Allocation Allocate(const std::vector<PlannedCapture>& captures, const std::vector<Eigen::MatrixXd>& a,
                    const std::vector<bool>& taken, const Eigen::VectorXd& allow, bool unbounded,
                    const PlanOptions& options, const std::vector<double>* from = nullptr) {
  Allocation out;
  out.lengths.assign(captures.size(), 0.0);
  for (size_t i = 0; i < captures.size(); ++i)
    if (taken[i]) out.lengths[i] = from ? std::max((*from)[i], captures[i].min_capture_s) : captures[i].min_capture_s;
  if ((allow.array() <= 0.0).any()) return out;
  for (;;) {
    const Eigen::MatrixXd cov = InverseInformation(a, out.lengths);
    if (cov.size() == 0) return out;
    Eigen::VectorXd weight = Eigen::VectorXd::Zero(kNumBaseParameters);  // the shortfall's gradient
    for (int j = 0; j < kNumBaseParameters; ++j)
      if (cov(j, j) > allow(j)) weight(j) = cov(j, j) / (allow(j) * allow(j));
    if (weight.isZero()) {
      out.met = true;
      return out;
    }
    // d cov_jj / d d_i = -(cov A_i cov)_jj, so the gain of capture i is trace(A_i M) with
    // M = sum_j weight_j cov_j cov_j^T.
    const Eigen::MatrixXd m = cov * weight.asDiagonal() * cov;
    int best = -1;
    double best_gain = 0.0;
    for (size_t i = 0; i < captures.size(); ++i) {
      const double cap = unbounded ? kUnboundedCaptureS : captures[i].max_capture_s;
      if (!taken[i] || out.lengths[i] >= cap) continue;
      const double gain = a[i].cwiseProduct(m).sum();
      if (gain > best_gain) {
        best_gain = gain;
        best = static_cast<int>(i);
      }
    }
    if (best < 0) return out;
    const auto b = static_cast<size_t>(best);
    const double cap = unbounded ? kUnboundedCaptureS : captures[b].max_capture_s;
    const double step = std::max(options.step_s, 0.05 * out.lengths[b]);
    out.lengths[b] = std::min(cap, out.lengths[b] + step);
  }
}

void AddTimes(const std::vector<PlannedCapture>& captures, const std::vector<double>& lengths,
              CapturePlan* plan) {
  std::set<std::string> mountings;
  plan->capture_s = plan->settle_s = plan->handling_s = 0.0;
  for (size_t i = 0; i < captures.size(); ++i) {
    if (!(lengths[i] > 0.0)) continue;
    plan->capture_s += lengths[i];
    plan->settle_s += captures[i].settle_s;
    plan->handling_s += captures[i].handling_s;
    if (!captures[i].mounting.empty() && mountings.insert(captures[i].mounting).second)
      plan->handling_s += captures[i].mounting_s;
  }
}

double TotalOf(const std::vector<PlannedCapture>& captures, const std::vector<double>& lengths) {
  CapturePlan p;
  AddTimes(captures, lengths, &p);
  return p.TotalS();
}

int CountTaken(const std::vector<bool>& taken) {
  return static_cast<int>(std::count(taken.begin(), taken.end(), true));
}

// Allocation for the taken set with type B taken at the allocation itself (it depends on the
// captures' relative weights): two passes.
Allocation AllocateWithTypeB(const std::vector<PlannedCapture>& captures,
                             const std::vector<Eigen::MatrixXd>& a, const std::vector<bool>& taken,
                             const PlannedSensor& sensor, const UncertaintyTarget& target,
                             bool unbounded, const PlanOptions& options) {
  std::vector<double> start(captures.size(), 0.0);
  for (size_t i = 0; i < captures.size(); ++i)
    if (taken[i]) start[i] = std::max(captures[i].min_capture_s, 10.0);
  Allocation out;
  out.lengths = start;
  std::vector<double> at = start;
  for (int pass = 0; pass < 2; ++pass) {
    const Eigen::MatrixXd cov = InverseInformation(a, at);
    if (cov.size() == 0) return out;
    const Eigen::VectorXd type_b = TypeBParts(captures, at, sensor, cov, options);
    out = Allocate(captures, a, taken, Allowances(target, sensor.nominal, type_b, options), unbounded,
                   options);
    if (!out.met) return out;
    at = out.lengths;
  }
  // The type-B part at the final lengths: when it moved the allowance past the lengths, go on
  // from them with the allowance it gives (a few rounds; the type-B part moves little).
  for (int round = 0; round < 4; ++round) {
    const Eigen::MatrixXd cov = InverseInformation(a, out.lengths);
    const Eigen::VectorXd type_b = TypeBParts(captures, out.lengths, sensor, cov, options);
    const Eigen::VectorXd allow = Allowances(target, sensor.nominal, type_b, options);
    bool met = true;
    for (int j = 0; j < kNumBaseParameters; ++j)
      if (cov(j, j) > allow(j)) met = false;
    if (met) return out;
    const std::vector<double> from = out.lengths;
    out = Allocate(captures, a, taken, allow, unbounded, options, &from);
    if (!out.met) return out;
  }
  out.met = false;
  return out;
}

}  // namespace

Eigen::Vector3d PlannedCapture::StaticForce(const Eigen::Vector3d& up, double gravity_mps2) {
  return gravity_mps2 * up.normalized();
}

Eigen::Vector3d PlannedCapture::TurntableForce(SensorAxis radial, SensorAxis up, double radius_m,
                                               double rpm, double gravity_mps2) {
  const double w = RpmToRadPerS(rpm);
  return -w * w * radius_m * SensorAxisVector(radial) + gravity_mps2 * SensorAxisVector(up);
}

bool UncertaintyTarget::Empty() const {
  return !std::isfinite(bias_counts) && !std::isfinite(scale_relative) && !std::isfinite(misalignment_rad);
}

double UncertaintyTarget::ForParameter(int index, const SensorModel& nominal) const {
  if (index <= kBiasZ) return bias_counts;
  if (index <= kScaleZ) return scale_relative * nominal.scale_counts_per_mps2(index - kScaleX);
  return misalignment_rad;
}

std::string PlanOptions::Validate() const {
  if (!(gravity_mps2 > 0.0)) return "gravity must be positive";
  if (!(coverage_factor > 0.0)) return "the coverage factor must be positive";
  if (!(margin > 0.0 && margin <= 1.0)) return "the margin must be in (0, 1]";
  if (!(step_s > 0.0)) return "the time step must be positive";
  if (min_captures < 0) return "min_captures must not be negative";
  return references.Validate();
}

Eigen::MatrixXd PredictCovariance(const std::vector<PlannedCapture>& captures,
                                  const std::vector<double>& lengths_s, const PlannedSensor& sensor,
                                  double gravity_mps2) {
  return InverseInformation(InformationPerSecond(captures, sensor, gravity_mps2), lengths_s);
}

std::vector<PlannedParameter> PredictUncertainty(const std::vector<PlannedCapture>& captures,
                                                 const std::vector<double>& lengths_s,
                                                 const PlannedSensor& sensor,
                                                 const UncertaintyTarget& target,
                                                 const PlanOptions& options) {
  std::vector<PlannedParameter> out(kNumBaseParameters);
  const Eigen::MatrixXd cov = PredictCovariance(captures, lengths_s, sensor, options.gravity_mps2);
  const Eigen::VectorXd type_b = cov.size() == 0 ? Eigen::VectorXd::Constant(kNumBaseParameters, kNaN)
                                                 : TypeBParts(captures, lengths_s, sensor, cov, options);
  for (int j = 0; j < kNumBaseParameters; ++j) {
    PlannedParameter& p = out[static_cast<size_t>(j)];
    p.index = j;
    p.target_expanded = target.ForParameter(j, sensor.nominal);
    p.type_b = type_b(j);
    p.predicted_a = cov.size() == 0 ? kNaN : std::sqrt(cov(j, j));
    p.predicted_expanded = options.coverage_factor * std::hypot(p.predicted_a, p.type_b);
    p.reachable = !std::isfinite(p.target_expanded) ||
                  options.coverage_factor * p.type_b < options.margin * p.target_expanded;
  }
  return out;
}

CapturePlan PlanCaptures(const std::vector<PlannedCapture>& captures, const PlannedSensor& sensor,
                         const UncertaintyTarget& target, const PlanOptions& options) {
  CapturePlan plan;
  if (const std::string why = options.Validate(); !why.empty()) {
    plan.message = why;
    return plan;
  }
  const std::vector<Eigen::MatrixXd> a = InformationPerSecond(captures, sensor, options.gravity_mps2);
  std::vector<bool> taken(captures.size(), true);
  Allocation best = AllocateWithTypeB(captures, a, taken, sensor, target, false, options);
  // Leave out the optional capture whose absence saves the most, while the target is still met.
  while (best.met) {
    const Eigen::MatrixXd cov = InverseInformation(a, best.lengths);
    const Eigen::VectorXd allow =
        Allowances(target, sensor.nominal, TypeBParts(captures, best.lengths, sensor, cov, options), options);
    int drop = -1;
    double drop_total = TotalOf(captures, best.lengths);
    for (size_t i = 0; i < captures.size(); ++i) {
      if (!taken[i] || !captures[i].optional || CountTaken(taken) - 1 < options.min_captures) continue;
      std::vector<bool> without = taken;
      without[i] = false;
      // Type B as at the current plan (it moves little with one capture fewer): the winner is
      // allocated again with its own below.
      Allocation trial = Allocate(captures, a, without, allow, false, options);
      if (!trial.met) continue;
      const double total = TotalOf(captures, trial.lengths);
      if (total < drop_total) {
        drop_total = total;
        drop = static_cast<int>(i);
      }
    }
    if (drop < 0) break;
    std::vector<bool> without = taken;
    without[static_cast<size_t>(drop)] = false;
    Allocation drop_alloc = AllocateWithTypeB(captures, a, without, sensor, target, false, options);
    if (!drop_alloc.met || TotalOf(captures, drop_alloc.lengths) >= TotalOf(captures, best.lengths)) break;
    taken = std::move(without);
    plan.buy_nothing.push_back(captures[static_cast<size_t>(drop)].id);
    best = std::move(drop_alloc);
  }
  if (!best.met) {
    // Keep the longest lengths the maximum allows, and say what it would take without it.
    for (size_t i = 0; i < captures.size(); ++i) best.lengths[i] = taken[i] ? captures[i].max_capture_s : 0.0;
    const Allocation unbounded = AllocateWithTypeB(captures, a, taken, sensor, target, true, options);
    if (unbounded.met) plan.unbounded_total_s = TotalOf(captures, unbounded.lengths);
  }
  plan.feasible = best.met;
  AddTimes(captures, best.lengths, &plan);
  if (best.met) plan.unbounded_total_s = plan.TotalS();
  plan.parameters = PredictUncertainty(captures, best.lengths, sensor, target, options);
  for (size_t i = 0; i < captures.size(); ++i) {
    PlannedLength l;
    l.id = captures[i].id;
    l.taken = best.lengths[i] > 0.0;
    l.capture_s = best.lengths[i];
    l.samples = l.taken ? std::lround(std::ceil(best.lengths[i] * sensor.rate_hz)) : 0;
    plan.captures.push_back(std::move(l));
  }
  if (!plan.feasible) {
    const bool type_b_bound = std::any_of(plan.parameters.begin(), plan.parameters.end(),
                                          [](const PlannedParameter& p) { return !p.reachable; });
    if (PredictCovariance(captures, best.lengths, sensor, options.gravity_mps2).size() == 0)
      plan.message = "the planned captures do not determine the nine parameters";
    else if (type_b_bound)
      plan.message = "the reference quantities' uncertainty alone exceeds the target";
    else
      plan.message = "the target needs captures longer than the procedure's maximum";
  }
  return plan;
}

CapturePlan PlanOfLengths(const std::vector<PlannedCapture>& captures, const std::vector<double>& lengths_s,
                          const PlannedSensor& sensor, const UncertaintyTarget& target,
                          const PlanOptions& options) {
  CapturePlan plan;
  AddTimes(captures, lengths_s, &plan);
  plan.parameters = PredictUncertainty(captures, lengths_s, sensor, target, options);
  plan.feasible = true;
  for (const PlannedParameter& p : plan.parameters) {
    if (!std::isfinite(p.predicted_a)) plan.feasible = false;  // the nine not determined
    if (std::isfinite(p.target_expanded) && !(p.predicted_expanded <= p.target_expanded)) plan.feasible = false;
  }
  if (!plan.feasible) plan.message = "the fixed lengths do not reach the target";
  plan.unbounded_total_s = plan.TotalS();
  for (size_t i = 0; i < captures.size(); ++i) {
    PlannedLength l;
    l.id = captures[i].id;
    l.taken = lengths_s[i] > 0.0;
    l.capture_s = lengths_s[i];
    l.samples = l.taken ? std::lround(std::ceil(lengths_s[i] * sensor.rate_hz - 1e-9)) : 0;
    plan.captures.push_back(std::move(l));
  }
  return plan;
}

}  // namespace accelcal
