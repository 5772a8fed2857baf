#include "accelcal/calibration/fit/least_squares.h"
#include "accelcal/calibration/fit/scaled_problem.h"
#include "accelcal/base/linear_algebra.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include <Eigen/QR>
#include <fmt/core.h>
#include <nlopt.hpp>

namespace accelcal {
namespace {

// Everything the objective needs (scaled_problem.h), and NLopt's count of its calls.
struct Problem : ScaledProblem {
  int evaluations = 0;
};

double Cost(const Problem& pr, const Eigen::VectorXd& p) {
  Eigen::VectorXd rho;
  pr.Evaluate(p, &rho, nullptr);
  const double cost = rho.squaredNorm();
  return std::isfinite(cost) ? cost : INFINITY;
}

double Objective(unsigned n, const double* x, double* grad, void* data) {
  Problem& pr = *static_cast<Problem*>(data);
  ++pr.evaluations;
  const Eigen::VectorXd p = pr.ToParameters(x);
  Eigen::VectorXd rho;
  Eigen::MatrixXd jac;
  pr.Evaluate(p, &rho, grad != nullptr ? &jac : nullptr);
  if (grad != nullptr) Eigen::Map<Eigen::VectorXd>(grad, n) = jac.transpose() * rho;
  const double cost = 0.5 * rho.squaredNorm();
  // A non-finite cost derails the line search; a large finite one makes it back off instead.
  return std::isfinite(cost) ? cost : 1e300;
}

std::string NloptResultName(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS: return "success";
    case nlopt::STOPVAL_REACHED: return "stopval_reached";
    case nlopt::FTOL_REACHED: return "ftol_reached";
    case nlopt::XTOL_REACHED: return "xtol_reached";
    case nlopt::MAXEVAL_REACHED: return "maxeval_reached";
    case nlopt::MAXTIME_REACHED: return "maxtime_reached";
    case nlopt::FAILURE: return "failure";
    case nlopt::INVALID_ARGS: return "invalid_args";
    case nlopt::OUT_OF_MEMORY: return "out_of_memory";
    case nlopt::ROUNDOFF_LIMITED: return "roundoff_limited";
    case nlopt::FORCED_STOP: return "forced_stop";
    default: return "unknown";
  }
}

// First stage: NLopt's SLSQP (L-BFGS's line search gave up near the optimum with a bare
// "failure" on ordinary bench sessions; SLSQP ends on its tolerance). The C++ wrapper throws on
// every negative result, including roundoff_limited, which usually still leaves a good x: we
// keep x either way and let the Gauss-Newton polish judge convergence.
Eigen::VectorXd RunNlopt(Problem& pr, int max_evaluations, std::string* result_name) {
  const int np = pr.NumFree();
  std::vector<double> x(np, 0.0);
  nlopt::opt opt(nlopt::LD_SLSQP, static_cast<unsigned>(np));
  opt.set_min_objective(Objective, &pr);
  // Loose enough to end on a tolerance rather than in round-off: the polish finishes the job.
  opt.set_ftol_rel(1e-10);
  opt.set_xtol_abs(1e-6);
  opt.set_maxeval(max_evaluations);
  double f = 0.0;
  try {
    *result_name = NloptResultName(opt.optimize(x, f));
  } catch (const nlopt::roundoff_limited&) {
    *result_name = "roundoff_limited";
  } catch (const std::exception& e) {
    *result_name = std::string("failure (") + e.what() + ")";
  }
  return pr.ToParameters(x.data());
}

// Empty when the Jacobian in the scaled free variables has full numerical rank; else which
// combination the captures cannot separate (determinacy.h's relative criterion, on the
// column-equilibrated matrix so that units do not matter).
std::string SingularStep(const Problem& pr, const Eigen::MatrixXd& jac) {
  const int nf = static_cast<int>(jac.cols());
  if (nf == 0) return {};
  Eigen::MatrixXd equilibrated = Eigen::MatrixXd::Zero(std::max<Eigen::Index>(jac.rows(), nf), nf);
  equilibrated.topRows(jac.rows()) = jac;
  for (int k = 0; k < nf; ++k) {
    const double norm = equilibrated.col(k).norm();
    if (!(norm > 0.0))
      return fmt::format("no capture is sensitive to {}", pr.model->ParameterLabel(pr.free[k]));
    equilibrated.col(k) /= norm;
  }
  const SingularValueDecomposition svd = DecomposeSvd(equilibrated);
  if (svd.values(nf - 1) > DeterminacyOptions{}.min_relative_singular_value * svd.values(0)) return {};
  Eigen::VectorXd direction = Eigen::VectorXd::Zero(pr.p0.size());
  for (int k = 0; k < nf; ++k) direction(pr.free[k]) = svd.v(k, nf - 1);
  return "the captures cannot separate " + DescribeCombination(*pr.model, direction.normalized());
}

struct PolishResult {
  Eigen::VectorXd p;
  int iterations = 0;
  bool converged = false;
  std::string failure;
};

// Second stage: Gauss-Newton with step halving, in the scaled variables.
PolishResult Polish(const Problem& pr, Eigen::VectorXd p, const LeastSquaresOptions& options) {
  PolishResult out;
  Eigen::VectorXd rho;
  Eigen::MatrixXd jac;
  for (out.iterations = 0; out.iterations < options.max_gauss_newton_iterations; ++out.iterations) {
    pr.Evaluate(p, &rho, &jac);
    if (!rho.allFinite() || !jac.allFinite()) {
      out.failure = "non-finite residuals (a capture's calibrated reading is undefined)";
      out.p = p;
      return out;
    }
    if (std::string why = SingularStep(pr, jac); !why.empty()) {
      out.failure = why;
      out.p = p;
      return out;
    }
    const Eigen::VectorXd step = jac.colPivHouseholderQr().solve(-rho);
    const double cost = rho.squaredNorm();
    double alpha = 1.0;
    Eigen::VectorXd candidate;
    Eigen::VectorXd rho_new;
    bool decreased = false;
    for (int halving = 0; halving < 40; ++halving, alpha *= 0.5) {
      candidate = p + pr.Step(alpha * step);
      pr.Evaluate(candidate, &rho_new, nullptr);
      if (rho_new.allFinite() && rho_new.squaredNorm() <= cost) {
        decreased = true;
        break;
      }
    }
    const double step_size = step.lpNorm<Eigen::Infinity>();
    const double new_cost = decreased ? rho_new.squaredNorm() : cost;
    if (decreased) p = candidate;
    const double predicted = (jac * step).squaredNorm();
    if (IsGaussNewtonConverged(step_size, cost, new_cost, predicted, options)) {
      out.converged = true;
      ++out.iterations;
      break;
    }
    if (!decreased) {
      out.failure = fmt::format("Gauss-Newton could not lower the cost (predicted decrease {:.3g})",
                                predicted);
      break;
    }
  }
  if (!out.converged && out.failure.empty())
    out.failure = fmt::format("no convergence after {} Gauss-Newton iterations",
                              options.max_gauss_newton_iterations);
  out.p = p;
  return out;
}

// Covariance, condition number and correlations at the solution (free parameters only; held
// ones get a NaN uncertainty and zero rows and columns).
void FillStatistics(const Problem& pr, const Eigen::VectorXd& p, const LeastSquaresOptions& options,
                    FitSummary* s) {
  Eigen::VectorXd rho;
  Eigen::MatrixXd jac;
  pr.Evaluate(p, &rho, &jac);
  const int n = static_cast<int>(rho.size());
  const int np = static_cast<int>(p.size());
  const int nf = pr.NumFree();
  s->chi2 = rho.squaredNorm();
  s->dof = n - nf;
  s->uncertainty_scale = s->dof > 0 ? std::sqrt(std::max(1.0, s->chi2 / s->dof)) : 1.0;

  // (J^T J)^-1 = V S^-2 V^T, from the SVD of J: better conditioned than the normal equations.
  Eigen::MatrixXd padded = Eigen::MatrixXd::Zero(std::max(n, nf), nf);
  padded.topRows(n) = jac;
  const SingularValueDecomposition svd = DecomposeSvd(padded);
  Eigen::VectorXd inv_sq(nf);
  for (int k = 0; k < nf; ++k)
    inv_sq(k) = svd.values(k) > 0.0 ? 1.0 / (svd.values(k) * svd.values(k)) : INFINITY;
  const Eigen::MatrixXd cov_free = svd.v * inv_sq.asDiagonal() * svd.v.transpose();
  s->covariance = Eigen::MatrixXd::Zero(np, np);
  const double scale2 = s->uncertainty_scale * s->uncertainty_scale;
  for (int a = 0; a < nf; ++a)
    for (int b = 0; b < nf; ++b)
      s->covariance(pr.free[a], pr.free[b]) =
          pr.scales(pr.free[a]) * cov_free(a, b) * pr.scales(pr.free[b]) * scale2;
  s->uncertainty = Eigen::VectorXd::Constant(np, kNaN);
  for (int k = 0; k < nf; ++k) s->uncertainty(pr.free[k]) = std::sqrt(s->covariance(pr.free[k], pr.free[k]));

  Eigen::MatrixXd equilibrated = padded;
  for (int k = 0; k < nf; ++k) equilibrated.col(k).normalize();
  const Eigen::VectorXd sv = SingularValues(equilibrated);
  s->condition_number = nf > 0 ? sv(0) / sv(nf - 1) : 1.0;

  for (int a = 0; a < nf; ++a) {
    for (int b = a + 1; b < nf; ++b) {
      const int i = pr.free[a], j = pr.free[b];
      const double rho_ab = s->covariance(i, j) / (s->uncertainty(i) * s->uncertainty(j));
      if (std::fabs(rho_ab) > std::fabs(s->most_correlated.rho)) s->most_correlated = {i, j, rho_ab};
    }
  }

  s->residuals.clear();
  double sum_sq = 0.0, max_abs = 0.0;
  for (int i = 0; i < n; ++i) {
    const FitCapture& c = (*pr.captures)[i];
    const double r = rho(i) * pr.sigmas(i);
    s->residuals.push_back({c.id, ReferenceMagnitudeMps2(c.kind, pr.gravity_mps2, c.radius_m, c.rpm),
                            r, pr.sigmas(i)});
    sum_sq += r * r;
    max_abs = std::max(max_abs, std::fabs(r));
  }
  s->residual_rms_mps2 = std::sqrt(sum_sq / n);
  s->residual_max_abs_mps2 = max_abs;

  if (s->condition_number > options.condition_warning)
    s->warnings.push_back(fmt::format(
        "poorly conditioned (condition number {:.3g} > {:.3g}): the poses do not constrain all "
        "parameters well; add poses or turntable runs along other directions",
        s->condition_number, options.condition_warning));
  if (std::fabs(s->most_correlated.rho) > options.correlation_warning)
    s->warnings.push_back(fmt::format("{} and {} are almost inseparable (rho = {:+.4f})",
                                      s->parameter_labels[s->most_correlated.first],
                                      s->parameter_labels[s->most_correlated.second],
                                      s->most_correlated.rho));
  if (s->dof == 0)
    s->warnings.push_back("no redundancy (as many captures as parameters): the residuals are zero "
                          "by construction and cannot check the calibration");
}

}  // namespace

bool IsGaussNewtonConverged(double step_size, double cost, double new_cost, double predicted,
                            const LeastSquaresOptions& options) {
  const bool stalled = cost - new_cost <= 1e-12 * (1.0 + cost);
  return step_size < options.step_tolerance || (stalled && predicted <= 1e-9 * (1.0 + cost));
}

std::string LeastSquaresOptions::Validate() const {
  if (!(gravity_mps2 > 0.0) || !std::isfinite(gravity_mps2)) return "gravity_mps2 must be positive";
  if (max_evaluations < 1) return "max_evaluations must be at least 1";
  if (max_gauss_newton_iterations < 1) return "max_gauss_newton_iterations must be at least 1";
  if (!(step_tolerance > 0.0)) return "step_tolerance must be positive";
  return {};
}

Eigen::VectorXd ResidualSigmas(const ResidualModel& model, const std::vector<FitCapture>& captures,
                               const Eigen::VectorXd& p, double gravity_mps2) {
  Eigen::VectorXd sigmas(captures.size());
  Eigen::Vector3d g;
  for (size_t i = 0; i < captures.size(); ++i) {
    model.Residual(p, captures[i], gravity_mps2, nullptr, &g);
    const double own_radius_mps2 = OwnRadiusSigma(model, captures[i], p, gravity_mps2);
    sigmas(i) = std::sqrt(g.dot(captures[i].mean_cov_counts2 * g) + own_radius_mps2 * own_radius_mps2);
  }
  return sigmas;
}

double OwnRadiusSigma(const ResidualModel& model, const FitCapture& capture,
                      const Eigen::VectorXd& p, double gravity_mps2) {
  if (capture.kind != CaptureKind::kTurntable || !(capture.radius_own_u_m > 0.0)) return 0.0;
  // Through the model's own residual (an adopted radius or speed effect changes how the radius
  // enters); a step far below any radius, far above the residual's rounding.
  constexpr double kStepM = 1e-5;
  FitCapture moved = capture;
  moved.radius_m = capture.radius_m + kStepM;
  const double plus = model.Residual(p, moved, gravity_mps2, nullptr, nullptr);
  moved.radius_m = capture.radius_m - kStepM;
  const double minus = model.Residual(p, moved, gravity_mps2, nullptr, nullptr);
  return std::fabs((plus - minus) / (2.0 * kStepM)) * capture.radius_own_u_m;
}

FitSummary SolveWeightedLeastSquares(const ResidualModel& model,
                                     const std::vector<FitCapture>& captures,
                                     const Eigen::VectorXd& initial,
                                     const LeastSquaresOptions& options) {
  FitSummary s;
  s.gravity_mps2 = options.gravity_mps2;
  s.num_captures = static_cast<int>(captures.size());
  for (int i = 0; i < model.NumParameters(); ++i) s.parameter_labels.push_back(model.ParameterLabel(i));
  if (const std::string e = options.Validate(); !e.empty()) {
    s.termination = FitTermination::kInvalidInput;
    s.message = e;
    return s;
  }

  Problem pr{MakeScaledProblem(model, captures, initial, options.held, options.gravity_mps2)};
  for (int i = 0; i < initial.size(); ++i)
    if (std::find(pr.free.begin(), pr.free.end(), i) == pr.free.end()) s.held.push_back({i, initial(i), {}});
  if (static_cast<int>(s.held.size()) != static_cast<int>(options.held.size())) {
    s.termination = FitTermination::kInvalidInput;
    s.message = "held parameters must be distinct indices of the model's parameters";
    return s;
  }
  if (!pr.sigmas.allFinite() || (pr.sigmas.array() <= 0.0).any() || !pr.scales.allFinite()) {
    s.termination = FitTermination::kNumericalFailure;
    s.message = "the initial guess gives undefined residual weights";
    return s;
  }

  Eigen::VectorXd p_nlopt = initial;
  if (options.warm_start) {
    s.optimizer_result = "skipped (warm start)";
  } else {
    p_nlopt = RunNlopt(pr, options.max_evaluations, &s.optimizer_result);
    s.optimizer_evaluations = pr.evaluations;
    // SLSQP can run off (to 1e40 from a poor start): polish from whichever is better.
    if (!(Cost(pr, p_nlopt) <= Cost(pr, initial))) {
      p_nlopt = initial;
      s.optimizer_result += " (worse than the initial guess: not used)";
    }
  }
  // Re-anchor weights and variable scales at NLopt's answer for the polish.
  pr.AnchorAt(p_nlopt);
  if (!pr.sigmas.allFinite() || (pr.sigmas.array() <= 0.0).any() || !pr.scales.allFinite()) {
    s.termination = FitTermination::kNumericalFailure;
    s.message = fmt::format("the optimizer ended ({}) at parameters where the residuals are "
                            "undefined", s.optimizer_result);
    return s;
  }
  const PolishResult polished = Polish(pr, p_nlopt, options);
  s.gauss_newton_iterations = polished.iterations;
  s.parameters = polished.p;
  if (!polished.converged) {
    s.termination = polished.failure.find("iterations") != std::string::npos
                        ? FitTermination::kNoConvergence
                        : FitTermination::kNumericalFailure;
    s.message = polished.failure + fmt::format(" (NLopt: {})", s.optimizer_result);
    return s;
  }
  FillStatistics(pr, polished.p, options, &s);
  bool finite = true;
  for (int i : pr.free) finite &= std::isfinite(s.uncertainty(i));
  if (!finite) {
    s.termination = FitTermination::kNumericalFailure;
    s.message = "the covariance is singular: some parameter is not determined by the captures";
    return s;
  }
  s.termination = FitTermination::kConverged;
  s.message = "converged";
  return s;
}

}  // namespace accelcal
