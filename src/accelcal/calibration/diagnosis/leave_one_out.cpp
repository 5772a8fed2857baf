#include "accelcal/calibration/diagnosis/leave_one_out.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/SVD>

#include "accelcal/calibration/fit/scaled_problem.h"

namespace accelcal {
namespace {

constexpr int kMaxWarmIterations = 3;  // Gauss-Newton iterations, the converging one included
// The one-capture update (below) is used only while the others still determine the fit: at a
// leverage h_ii above this the capture carries nearly all the information on some combination
// of parameters, the rank-one downdate divides by 1 - h_ii < 1e-3, and the fit without it moves
// far (hundreds of scaled units on the Xsens data, where the held-Jacobian steps do not settle):
// refit instead.
constexpr double kMaxLeverage = 0.999;
constexpr int kMaxChordIterations = 6;  // steps with one Jacobian held
// Jacobians evaluated per capture before a refit decides. Large residuals make Gauss-Newton
// converge linearly: on the Xsens file 336 of the 338 fits without one capture took 1 to 5 (a
// limit of 3 sent 16 of them to the full NLopt solve; now 2 go, whose steps do not settle). The
// printout of that file is the same as with refits throughout, and so are the 700 runs of the
// physics bench (tests/physics): the same tallies, calibration files the same to 1e-6.
constexpr int kMaxJacobianChecks = 8;
// A weighted Jacobian whose smallest singular value is below this fraction of its largest: the
// update, which solves normal equations (squaring the condition number), is not used; the
// refits then also say what the captures do not determine.
constexpr double kMinRelativeSingularValue = 1e-6;

// The fit of all captures, linearised: the problem in the solver's scaled free variables
// anchored at p_full (scaled_problem.h), its weighted residuals rho and Jacobian J there, and
// J's SVD.
struct Linearised {
  ScaledProblem problem;
  Eigen::VectorXd rho;            // r_i / sigma_i at p_full
  Eigen::MatrixXd jac;            // d rho_i / d x_k
  Eigen::MatrixXd u, v;           // thin SVD: jac = u diag(s) v^T
  Eigen::VectorXd s;
  bool usable = false;

  // A^-1 b with A = J^T J.
  Eigen::VectorXd SolveNormal(const Eigen::VectorXd& b) const {
    return v * (s.array().square().inverse().matrix().asDiagonal() * (v.transpose() * b));
  }
};

// The weighted residuals (and, with `jac`, the weighted Jacobian) of every capture at x, the
// step from p_full; false when any is not finite.
bool EvaluateAt(const Linearised& lin, const Eigen::VectorXd& x, Eigen::VectorXd* rho,
                Eigen::MatrixXd* jac) {
  lin.problem.Evaluate(lin.problem.ToParameters(x), rho, jac);
  return rho->allFinite() && (jac == nullptr || jac->allFinite());
}

Linearised Linearise(const ResidualModel& model, const std::vector<FitCapture>& captures,
                     const Eigen::VectorXd& p_full, const LeastSquaresOptions& solver) {
  Linearised lin;
  lin.problem = MakeScaledProblem(model, captures, p_full, solver.held, solver.gravity_mps2);
  const int n = static_cast<int>(captures.size());
  const int nf = lin.problem.NumFree();
  const bool finite = EvaluateAt(lin, Eigen::VectorXd::Zero(nf), &lin.rho, &lin.jac);
  if (nf == 0 || n <= nf + 1 || !finite) return lin;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(lin.jac, Eigen::ComputeThinU | Eigen::ComputeThinV);
  lin.u = svd.matrixU();
  lin.v = svd.matrixV();
  lin.s = svd.singularValues();
  lin.usable = lin.s(nf - 1) > kMinRelativeSingularValue * lin.s(0);
  return lin;
}

struct LeftOutFit {
  Eigen::VectorXd p;        // the parameters without the capture
  double extra_var = 0.0;   // g^T C_(-i) g, m/s^2 squared: the prediction's own spread
};

// The polish's test (IsGaussNewtonConverged) of a Gauss-Newton step at x for the captures but i
// (large residuals make Gauss-Newton converge only linearly: the refits often stop by its
// round-off rule). Takes the step into *x when it lowers the cost.
bool IsPolishConverged(const Linearised& lin, int i, const Eigen::MatrixXd& jac,
                       const Eigen::VectorXd& rho, const Eigen::VectorXd& step,
                       const LeastSquaresOptions& solver, Eigen::VectorXd* x) {
  const double cost = rho.squaredNorm() - rho(i) * rho(i);
  Eigen::VectorXd jstep = jac * step;
  jstep(i) = 0.0;
  const double predicted = jstep.squaredNorm();
  const Eigen::VectorXd candidate = *x + step;
  Eigen::VectorXd rho_new;
  double new_cost = cost;
  if (EvaluateAt(lin, candidate, &rho_new, nullptr)) {
    const double c = rho_new.squaredNorm() - rho_new(i) * rho_new(i);
    if (c <= cost) {
      new_cost = c;
      *x = candidate;
    }
  }
  return IsGaussNewtonConverged(step.lpNorm<Eigen::Infinity>(), cost, new_cost, predicted, solver);
}

// The fit without capture i from the full fit, without a solve from scratch. The rank-one
// (Sherman-Morrison) downdate of the normal equations gives the step to the fit of the others,
// x = A^-1 J_i^T rho_i / (1 - h_ii) (exact for a linear model). Gauss-Newton steps with the
// Jacobian held (each costs one evaluation of the residuals) settle it; but with the Jacobian
// held they settle where J_held^T rho = 0, not where the others' cost is least (off by
// A^-1 (J - J_held)^T rho: a few % of an outlier's prediction), so the Jacobian is then
// evaluated where they settled and its Gauss-Newton step taken: when the polish's own test
// (IsPolishConverged) says converged, that is the minimum a refit would stop at; else the steps
// go on with the new Jacobian held. False when the capture's leverage is too high or the
// steps do not settle by then: the caller refits.
bool UpdateLeftOut(const Linearised& lin, int i, const LeastSquaresOptions& solver,
                   LeftOutFit* out) {
  const double h = lin.u.row(i).squaredNorm();
  if (!(h < kMaxLeverage)) return false;
  const Eigen::VectorXd ji = lin.jac.row(i).transpose();
  const Eigen::VectorXd a_inv_ji = lin.SolveNormal(ji);
  Eigen::VectorXd x = a_inv_ji * (lin.rho(i) / (1.0 - h));
  // The normal matrix of the others from a Jacobian of every capture.
  const auto others_normal = [i](const Eigen::MatrixXd& jac) -> Eigen::LDLT<Eigen::MatrixXd> {
    const Eigen::VectorXd row = jac.row(i).transpose();
    return Eigen::LDLT<Eigen::MatrixXd>(jac.transpose() * jac - row * row.transpose());
  };
  // J_(-i)^T rho_(-i): the gradient of the others' cost (halved).
  const auto others_gradient = [i](const Eigen::MatrixXd& jac, const Eigen::VectorXd& rho) -> Eigen::VectorXd {
    return jac.transpose() * rho - jac.row(i).transpose() * rho(i);
  };
  Eigen::MatrixXd held = lin.jac;
  Eigen::LDLT<Eigen::MatrixXd> held_normal = others_normal(held);
  Eigen::VectorXd rho;
  Eigen::MatrixXd jac;
  for (int check = 0; check < kMaxJacobianChecks; ++check) {
    bool settled = false;
    for (int it = 0; it < kMaxChordIterations && !settled; ++it) {
      if (!EvaluateAt(lin, x, &rho, nullptr)) return false;
      const Eigen::VectorXd step = -held_normal.solve(others_gradient(held, rho));
      x += step;
      settled = step.lpNorm<Eigen::Infinity>() < solver.step_tolerance;
    }
    if (!settled) return false;
    if (!EvaluateAt(lin, x, &rho, &jac)) return false;
    held_normal = others_normal(jac);
    if (held_normal.info() != Eigen::Success) return false;
    const Eigen::VectorXd step = -held_normal.solve(others_gradient(jac, rho));
    if (IsPolishConverged(lin, i, jac, rho, step, solver, &x)) {
      out->p = lin.problem.ToParameters(x);
      // g^T C_(-i) g = sigma_i^2 J_i (J_(-i)^T J_(-i))^-1 J_i^T, weighted rows at the fit.
      const Eigen::VectorXd row = jac.row(i).transpose();
      const double sigma = lin.problem.sigmas(i);
      out->extra_var = sigma * sigma * row.dot(held_normal.solve(row));
      return true;
    }
    held = jac;
  }
  return false;
}

// The fit without capture i by refitting: Gauss-Newton warm-started at p_full, the full solve
// when that does not converge; p_full itself (with no spread) when both fail.
LeftOutFit RefitLeftOut(const ResidualModel& model, const std::vector<FitCapture>& captures,
                        const Eigen::VectorXd& p_full, size_t i, const LeastSquaresOptions& solver) {
  std::vector<FitCapture> rest;
  for (size_t j = 0; j < captures.size(); ++j)
    if (j != i) rest.push_back(captures[j]);
  // Without one capture the minimum usually moves little from p_full: Gauss-Newton from there
  // reaches the same minimum as the full solve (by the same convergence test) at a fraction of
  // the cost. When it needs more than kMaxWarmIterations steps the capture moved the fit far
  // (a candidate model that bends to single captures): Gauss-Newton alone then sometimes stops
  // in a worse minimum than NLopt + Gauss-Newton (seen on the Xsens data: chi2 413 against
  // 401), so the full solve decides, as it does when the warm one fails.
  LeastSquaresOptions warm = solver;
  warm.warm_start = true;
  warm.max_gauss_newton_iterations = kMaxWarmIterations;  // not converged by then: not usable
  FitSummary s = SolveWeightedLeastSquares(model, rest, p_full, warm);
  if (!s.IsUsable()) s = SolveWeightedLeastSquares(model, rest, p_full, solver);
  LeftOutFit out{s.IsUsable() ? s.parameters : p_full, 0.0};
  if (s.IsUsable() && s.uncertainty_scale > 0.0) {
    Eigen::VectorXd grad(model.NumParameters());  // the base model writes it unsized
    model.Residual(out.p, captures[i], solver.gravity_mps2, &grad, nullptr);
    // The fit's covariance carries the factor max(1, chi2/dof); the noise-only one does not.
    const double unscale = 1.0 / (s.uncertainty_scale * s.uncertainty_scale);
    out.extra_var = unscale * grad.dot(s.covariance * grad);
  }
  return out;
}

}  // namespace

LeaveOneOutResult PredictLeftOut(const ResidualModel& model, const std::vector<FitCapture>& captures,
                                 const Eigen::VectorXd& p_full, const LeastSquaresOptions& solver) {
  LeaveOneOutResult out;
  const Linearised lin = Linearise(model, captures, p_full, solver);
  double sum_sq = 0.0, chi2 = 0.0;
  for (size_t i = 0; i < captures.size(); ++i) {
    LeftOutFit fit;
    if (!lin.usable || !UpdateLeftOut(lin, static_cast<int>(i), solver, &fit)) {
      fit = RefitLeftOut(model, captures, p_full, i, solver);
      ++out.refitted;
    }
    const double r = model.Residual(fit.p, captures[i], solver.gravity_mps2, nullptr, nullptr);
    const double sigma = lin.problem.sigmas(static_cast<Eigen::Index>(i));
    LeaveOneOutPrediction pred{captures[i].id, r, r / std::sqrt(sigma * sigma + fit.extra_var)};
    sum_sq += r * r;
    chi2 += pred.z * pred.z;
    if (!(std::fabs(pred.z) <= out.worst_abs_z)) {
      out.worst_abs_z = std::fabs(pred.z);
      out.worst_index = static_cast<int>(i);
    }
    out.predictions.push_back(pred);
  }
  out.rms_mps2 = captures.empty() ? kNaN : std::sqrt(sum_sq / static_cast<double>(captures.size()));
  out.chi2 = chi2;
  return out;
}

double WorstOfNormalsPValue(double abs_z, int n) {
  if (!(abs_z >= 0.0) || n <= 0) return 1.0;
  const double single = std::erfc(abs_z / std::sqrt(2.0));  // P(|N(0,1)| > z)
  // 1 - (1 - p)^n, accurate for small p.
  return -std::expm1(static_cast<double>(n) * std::log1p(-std::min(single, 1.0 - 1e-16)));
}

}  // namespace accelcal
