#include "accelcal/calibration/uncertainty_budget.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include <Eigen/QR>

#include "accelcal/base/student_t.h"
#include "accelcal/calibration/fit/least_squares.h"

namespace accelcal {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Central-difference steps of the reference quantities: small against any stated uncertainty,
// large against rounding of residuals of ~1e-3 m/s^2.
constexpr double kGravityStepMps2 = 1e-4;
constexpr double kRadiusStepM = 1e-4;
constexpr double kRpmStepRelative = 1e-4;
constexpr double kTiltStepRad = 1e-3;

bool Stated(double u) { return std::isfinite(u); }

// Residuals of every capture at p when each capture is first changed by `perturb` (which also
// returns the gravity to evaluate it with).
using Perturbation = std::function<double(FitCapture&)>;

Eigen::VectorXd Residuals(const ResidualModel& model, const std::vector<FitCapture>& captures,
                          const Eigen::VectorXd& p, const Perturbation& perturb) {
  Eigen::VectorXd r(static_cast<Eigen::Index>(captures.size()));
  for (size_t i = 0; i < captures.size(); ++i) {
    FitCapture c = captures[i];
    const double g = perturb(c);
    r(static_cast<Eigen::Index>(i)) = model.Residual(p, c, g, nullptr, nullptr);
  }
  return r;
}

// The fit's linear response: the change of the fitted parameters (all of p; held ones 0) for a
// change dr of the residuals, dp = -(J^T W J)^-1 J^T W dr.
class LinearResponse {
 public:
  LinearResponse(const ResidualModel& model, const std::vector<FitCapture>& captures,
                 const FitSummary& fit, double gravity_mps2)
      : np_(static_cast<int>(fit.parameters.size())) {
    for (int j = 0; j < np_; ++j)
      if (!fit.IsHeld(j)) free_.push_back(j);
    const Eigen::VectorXd sigma = ResidualSigmas(model, captures, fit.parameters, gravity_mps2);
    const auto n = static_cast<Eigen::Index>(captures.size());
    Eigen::MatrixXd jw(n, static_cast<Eigen::Index>(free_.size()));
    Eigen::VectorXd grad(np_);
    for (Eigen::Index i = 0; i < n; ++i) {
      model.Residual(fit.parameters, captures[static_cast<size_t>(i)], gravity_mps2, &grad, nullptr);
      for (size_t k = 0; k < free_.size(); ++k) jw(i, static_cast<Eigen::Index>(k)) = grad(free_[k]) / sigma(i);
    }
    inv_sigma_ = sigma.cwiseInverse();
    qr_ = jw.colPivHouseholderQr();
  }

  Eigen::VectorXd Solve(const Eigen::VectorXd& dr) const {
    const Eigen::VectorXd dp_free = qr_.solve(Eigen::VectorXd(-dr.cwiseProduct(inv_sigma_)));
    Eigen::VectorXd dp = Eigen::VectorXd::Zero(np_);
    for (size_t k = 0; k < free_.size(); ++k) dp(free_[k]) = dp_free(static_cast<Eigen::Index>(k));
    return dp;
  }

 private:
  int np_;
  std::vector<int> free_;
  Eigen::VectorXd inv_sigma_;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr_;
};

// One reference quantity: how to perturb the captures by `step` of it, whether the captures
// depend on it, and its standard uncertainty.
struct ReferenceInput {
  std::string name;
  std::string unit;
  double u = kNaN;
  double step = 0.0;
  bool second_order = false;  // zero first derivative: the GUM's higher-order term
  bool unused = false;        // the method does not use it: sensitivity 0
  std::string note;
  std::function<double(FitCapture&, double)> apply;  // returns the gravity to use
};

bool HasTurntable(const std::vector<FitCapture>& captures) {
  for (const FitCapture& c : captures)
    if (c.kind == CaptureKind::kTurntable) return true;
  return false;
}

std::vector<ReferenceInput> Inputs(const ReferenceUncertainties& u, double g, bool turntable) {
  std::vector<ReferenceInput> in;
  in.push_back({"gravity", "m/s^2", u.gravity_mps2, kGravityStepMps2, false, false, "",
                [g](FitCapture&, double d) { return g + d; }});
  if (turntable) {
    in.push_back({"radius", "m", u.radius_m, kRadiusStepM, false, false,
                  "one reading error common to every turntable run",
                  [g](FitCapture& c, double d) {
                    if (c.kind == CaptureKind::kTurntable) c.radius_m += d;
                    return g;
                  }});
    in.push_back({"turntable speed", "1", u.rpm_relative, kRpmStepRelative, false, false,
                  "relative; common to every run",
                  [g](FitCapture& c, double d) {
                    if (c.kind == CaptureKind::kTurntable) c.rpm *= 1.0 + d;
                    return g;
                  }});
    in.push_back({"table tilt", "rad", u.table_tilt_rad, kTiltStepRad, true, false,
                  "second order: turntable runs see g cos(tilt); u = |c| u^2 / sqrt(2)",
                  [g](FitCapture& c, double d) {
                    return c.kind == CaptureKind::kTurntable ? g * std::cos(d) : g;
                  }});
  }
  in.push_back({"prism squareness", "rad", u.prism_squareness_rad, 0.0, false, true,
                "not used: the magnitude method never uses a pose's direction", nullptr});
  return in;
}

// The runs' own radius uncertainties (FitCapture::radius_own_u_m), each run's its own input:
// the variance each leaves in every parameter, summed (independent runs), and their RMS, m.
// `variance` is empty when no run has one.
struct OwnRadiusPart {
  Eigen::VectorXd variance;
  double rms_u_m = 0.0;
};

OwnRadiusPart OwnRadiusVariance(const ResidualModel& model, const std::vector<FitCapture>& captures,
                                const FitSummary& fit, double gravity_mps2,
                                const LinearResponse& response) {
  OwnRadiusPart part;
  double sum_u2 = 0.0;
  int runs = 0;
  for (size_t i = 0; i < captures.size(); ++i) {
    const double sigma_mps2 = OwnRadiusSigma(model, captures[i], fit.parameters, gravity_mps2);
    if (!(sigma_mps2 > 0.0)) continue;
    if (part.variance.size() == 0) part.variance = Eigen::VectorXd::Zero(fit.parameters.size());
    Eigen::VectorXd dr = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(captures.size()));
    dr(static_cast<Eigen::Index>(i)) = sigma_mps2;
    part.variance += response.Solve(dr).cwiseAbs2();
    sum_u2 += captures[i].radius_own_u_m * captures[i].radius_own_u_m;
    ++runs;
  }
  if (runs > 0) part.rms_u_m = std::sqrt(sum_u2 / runs);
  return part;
}

double WelchSatterthwaite(const std::vector<BudgetContribution>& parts, double combined) {
  double denominator = 0.0;
  for (const BudgetContribution& b : parts)
    if (std::isfinite(b.dof) && b.dof > 0.0 && b.contribution > 0.0)
      denominator += std::pow(b.contribution, 4) / b.dof;
  return denominator > 0.0 ? std::pow(combined, 4) / denominator : kInfinity;
}

}  // namespace

std::string ReferenceUncertainties::Validate() const {
  const double all[] = {gravity_mps2, radius_m, rpm_relative, table_tilt_rad, prism_squareness_rad};
  for (double v : all)
    if (!std::isnan(v) && !(std::isfinite(v) && v >= 0.0))
      return "a reference uncertainty must be a finite number >= 0";
  return {};
}

const ParameterBudget* UncertaintyBudget::Find(int index) const {
  for (const ParameterBudget& p : parameters)
    if (p.index == index) return &p;
  return nullptr;
}

UncertaintyBudget MakeUncertaintyBudget(const ResidualModel& model,
                                        const std::vector<FitCapture>& captures,
                                        const FitSummary& fit, double gravity_mps2,
                                        const ReferenceUncertainties& references) {
  UncertaintyBudget budget;
  budget.coverage_probability = kCoverageProbability;
  if (!fit.IsUsable() || captures.empty()) return budget;
  const LinearResponse response(model, captures, fit, gravity_mps2);
  const std::vector<ReferenceInput> inputs =
      Inputs(references, gravity_mps2, HasTurntable(captures));

  // Sensitivities of every parameter to each input (first or second derivative).
  std::vector<Eigen::VectorXd> sensitivity;
  for (const ReferenceInput& in : inputs) {
    if (in.unused) {
      sensitivity.push_back(Eigen::VectorXd::Zero(fit.parameters.size()));
      continue;
    }
    const auto at = [&](double d) {
      return Residuals(model, captures, fit.parameters, [&](FitCapture& c) { return in.apply(c, d); });
    };
    const Eigen::VectorXd plus = at(in.step), minus = at(-in.step);
    const Eigen::VectorXd dr = in.second_order
                                   ? Eigen::VectorXd((plus + minus - 2.0 * at(0.0)) / (in.step * in.step))
                                   : Eigen::VectorXd((plus - minus) / (2.0 * in.step));
    sensitivity.push_back(response.Solve(dr));
    if (!Stated(in.u)) budget.not_stated.push_back(in.name);
  }

  // The fit weighed each run by its own radius uncertainty as well as by its noise, so its
  // covariance (J^T W J)^-1 holds both: the noise's part (type A) and the radii's, which is
  // exactly what propagating each run's radius error as an input gives (GUM 5.1, each run
  // independent). Listed apart; the type A keeps the fit's scale for excess scatter. A fit
  // whose uncertainty comes from the captures' scatter (fit.scatter) has the radii in it.
  const OwnRadiusPart own_radius =
      fit.scatter ? OwnRadiusPart{} : OwnRadiusVariance(model, captures, fit, gravity_mps2, response);
  const double dof_a = fit.uncertainty_scale > 1.0 && fit.dof > 0 ? fit.dof : kInfinity;
  for (int j = 0; j < kNumBaseParameters && j < fit.parameters.size(); ++j) {
    if (fit.IsHeld(j)) continue;
    ParameterBudget pb;
    pb.index = j;
    pb.name = std::string(ParameterName(j));
    pb.unit = std::string(ParameterUnit(j));
    pb.value = fit.parameters(j);
    const double own_radius_var = own_radius.variance.size() > 0 ? own_radius.variance(j) : 0.0;
    const double scale2 = fit.uncertainty_scale * fit.uncertainty_scale;
    const double u_a = std::sqrt(std::max(0.0, fit.covariance(j, j) - scale2 * own_radius_var));
    pb.contributions.push_back({"fit (type A)", 'A', u_a, pb.unit, 1.0, u_a, dof_a,
                                dof_a == kInfinity ? "the captures' own noise"
                                                   : "scaled by the residuals' scatter"});
    double u2 = u_a * u_a;
    if (own_radius.variance.size() > 0) {
      const double part = std::sqrt(own_radius_var);
      pb.contributions.push_back(
          {kOwnRadiusQuantity, 'B', own_radius.rms_u_m, "m",
           own_radius.rms_u_m > 0.0 ? part / own_radius.rms_u_m : 0.0, part, kInfinity,
           "each run's own (a board off the plate's reference: the plate set down anew); u the "
           "runs' RMS, c their root sum of squares"});
      u2 += part * part;
    }
    for (size_t q = 0; q < inputs.size(); ++q) {
      const ReferenceInput& in = inputs[q];
      BudgetContribution b{in.name, 'B', in.u, in.unit, sensitivity[q](j), 0.0, kInfinity, in.note};
      if (Stated(in.u)) {
        b.contribution = in.second_order ? std::fabs(b.sensitivity) * in.u * in.u / std::sqrt(2.0)
                                         : std::fabs(b.sensitivity) * in.u;
      } else if (!in.unused) {
        b.note = "not stated";
      }
      u2 += b.contribution * b.contribution;
      pb.contributions.push_back(std::move(b));
    }
    pb.combined = std::sqrt(u2);
    pb.effective_dof = WelchSatterthwaite(pb.contributions, pb.combined);
    pb.coverage_factor = StudentTCoverageFactor(budget.coverage_probability, pb.effective_dof);
    pb.expanded = pb.coverage_factor * pb.combined;
    budget.parameters.push_back(std::move(pb));
  }
  return budget;
}

}  // namespace accelcal
