#include "accelcal/calibration/fit/scatter_uncertainty.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <fmt/core.h>

#include "accelcal/calibration/fit/scaled_problem.h"

namespace accelcal {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The smallest degrees of freedom the t-inflation uses: below 3 a t-distribution's standard
// deviation grows without bound (and is infinite at 2); such a fit is limited by its scatter
// whatever the number.
constexpr double kMinInflationDof = 3.0;

// C of a structure (counts^2 per unit lambda), n x n, from the captures' mean times.
Eigen::MatrixXd StructureCovariance(ScatterStructure structure, const std::vector<FitCapture>& captures,
                                    const ScatterUncertaintyOptions& options) {
  const int n = static_cast<int>(captures.size());
  if (structure == ScatterStructure::kIndependent) return Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd gamma(n, n);  // the variogram E[(e_i - e_j)^2] per unit lambda
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double dt = std::fabs(captures[i].mean_t_s - captures[j].mean_t_s);
      gamma(i, j) = structure == ScatterStructure::kRandomWalk
                        ? dt
                        : 4.0 / kPi * std::log1p(dt / options.flicker_t0_s);
    }
  const Eigen::MatrixXd centre =
      Eigen::MatrixXd::Identity(n, n) - Eigen::MatrixXd::Constant(n, n, 1.0 / n);
  return -0.5 * centre * gamma * centre;
}

bool HaveTimes(const std::vector<FitCapture>& captures) {
  for (const FitCapture& c : captures)
    if (!std::isfinite(c.mean_t_s)) return false;
  return true;
}

// The restricted log-likelihood of the contrasts (rotated to M's eigenbasis: z2 = their
// squares, lambdas M's eigenvalues) at variance `lambda`, less its constant.
double RestrictedLogLikelihood(const Eigen::VectorXd& z2, const Eigen::VectorXd& eig, double lambda) {
  double sum = 0.0;
  for (int k = 0; k < z2.size(); ++k) {
    const double v = 1.0 + lambda * eig(k);
    sum += std::log(v) + z2(k) / v;
  }
  return -0.5 * sum;
}

// The REML estimate of lambda >= 0: golden-section search on log(lambda) over a range set by
// the eigenvalues (the likelihood of one variance component over such contrasts is unimodal in
// practice; the bracket's ends are checked too).
double MaximizeRestricted(const Eigen::VectorXd& z2, const Eigen::VectorXd& eig) {
  const double largest = eig.maxCoeff();
  if (!(largest > 0.0)) return 0.0;
  // lambda * largest from 1e-6 to 1e8: from no effect to far beyond any bench's scatter.
  double lo = std::log(1e-6 / largest), hi = std::log(1e8 / largest);
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  auto f = [&](double x) { return RestrictedLogLikelihood(z2, eig, std::exp(x)); };
  double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
  double fa = f(a), fb = f(b);
  for (int it = 0; it < 200 && hi - lo > 1e-9; ++it) {
    if (fa > fb) {
      hi = b; b = a; fb = fa; a = hi - golden * (hi - lo); fa = f(a);
    } else {
      lo = a; a = b; fa = fb; b = lo + golden * (hi - lo); fb = f(b);
    }
  }
  const double best = std::exp(0.5 * (lo + hi));
  return RestrictedLogLikelihood(z2, eig, 0.0) >= RestrictedLogLikelihood(z2, eig, best) ? 0.0 : best;
}

// The Fisher information of lambda in the restricted likelihood: 1/2 sum (e_k / (1 + lambda e_k))^2.
double FisherInformation(const Eigen::VectorXd& eig, double lambda) {
  double sum = 0.0;
  for (int k = 0; k < eig.size(); ++k) {
    const double q = eig(k) / (1.0 + lambda * eig(k));
    sum += q * q;
  }
  return 0.5 * sum;
}

}  // namespace

ScatterFit FitScatter(const ResidualModel& model, const std::vector<FitCapture>& captures,
                      const FitSummary& fit, const ScatterUncertaintyOptions& options) {
  ScatterFit out;
  const int n = static_cast<int>(captures.size());
  if (!fit.IsUsable() || fit.dof <= 0 || static_cast<int>(fit.residuals.size()) != n) return out;
  std::vector<int> held;
  for (const HeldParameter& h : fit.held) held.push_back(h.index);
  ScaledProblem pr = MakeScaledProblem(model, captures, fit.parameters, held, fit.gravity_mps2);
  for (int i = 0; i < n; ++i) pr.sigmas(i) = fit.residuals[static_cast<size_t>(i)].sigma_mps2;
  Eigen::VectorXd rho;
  Eigen::MatrixXd jac;  // whitened, in the scaled free variables
  pr.Evaluate(fit.parameters, &rho, &jac);
  const int nf = pr.NumFree();
  if (n - nf <= 0 || !jac.allFinite() || !rho.allFinite()) return out;

  // Q1 spans the whitened Jacobian, Q2 its complement: the error contrasts z = Q2^T rho.
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(jac);
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd q2 = q.rightCols(n - nf);
  const Eigen::VectorXd z = q2.transpose() * rho;
  // The weighted least-squares map from whitened residual errors to the scaled parameters,
  // A_w = (Jw^T Jw)^-1 Jw^T, and the noise-only covariance (Jw^T Jw)^-1.
  const Eigen::MatrixXd normal_inv = (jac.transpose() * jac).inverse();
  const Eigen::MatrixXd a_w = normal_inv * jac.transpose();

  // g_i / sigma_i: a capture's whitened residual per count of its mean.
  Eigen::MatrixXd g(n, 3);
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d grad_raw;
    model.Residual(fit.parameters, captures[static_cast<size_t>(i)], fit.gravity_mps2, nullptr, &grad_raw);
    g.row(i) = grad_raw.transpose() / pr.sigmas(i);
  }
  const Eigen::MatrixXd gg = g * g.transpose();

  std::vector<ScatterStructure> structures = {ScatterStructure::kIndependent};
  if (HaveTimes(captures)) {
    structures.push_back(ScatterStructure::kFlicker);
    structures.push_back(ScatterStructure::kRandomWalk);
  }
  struct Tried {
    double lambda = 0.0;
    Eigen::VectorXd eig;
    Eigen::MatrixXd s_w;  // whitened structure covariance, n x n
  };
  std::vector<Tried> tried;
  for (ScatterStructure structure : structures) {
    Tried t;
    t.s_w = gg.cwiseProduct(StructureCovariance(structure, captures, options));
    const Eigen::MatrixXd m = q2.transpose() * t.s_w * q2;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (m + m.transpose()));
    t.eig = es.eigenvalues().cwiseMax(0.0);
    const Eigen::VectorXd z2 = (es.eigenvectors().transpose() * z).cwiseAbs2();
    t.lambda = MaximizeRestricted(z2, t.eig);
    out.candidates.push_back({structure, std::sqrt(t.lambda), RestrictedLogLikelihood(z2, t.eig, t.lambda)});
    tried.push_back(std::move(t));
  }
  out.chosen = 0;
  for (int k = 1; k < static_cast<int>(out.candidates.size()); ++k)
    if (out.candidates[static_cast<size_t>(k)].log_likelihood >
        out.candidates[static_cast<size_t>(out.chosen)].log_likelihood)
      out.chosen = k;
  const Tried& best = tried[static_cast<size_t>(out.chosen)];

  // The sandwich, in the scaled variables, then in the parameters' units.
  const Eigen::MatrixXd extra = a_w * best.s_w * a_w.transpose();
  const double var_lambda = 1.0 / FisherInformation(best.eig, best.lambda);
  const int np = static_cast<int>(fit.parameters.size());
  out.covariance = Eigen::MatrixXd::Zero(np, np);
  out.uncertainty = Eigen::VectorXd::Constant(np, kNaN);
  out.dof = Eigen::VectorXd::Constant(np, kNaN);
  for (int a = 0; a < nf; ++a) {
    for (int b = 0; b < nf; ++b) {
      const int i = pr.free[static_cast<size_t>(a)], j = pr.free[static_cast<size_t>(b)];
      out.covariance(i, j) = pr.scales(i) * (normal_inv(a, b) + best.lambda * extra(a, b)) * pr.scales(j);
    }
    const int i = pr.free[static_cast<size_t>(a)];
    const double v = normal_inv(a, a) + best.lambda * extra(a, a);
    const double per_lambda = extra(a, a);
    const double nu = per_lambda > 0.0 ? 2.0 * v * v / (per_lambda * per_lambda * var_lambda) : INFINITY;
    out.dof(i) = nu;
    const double inflation = std::isfinite(nu) ? std::sqrt(std::max(nu, kMinInflationDof) /
                                                           (std::max(nu, kMinInflationDof) - 2.0))
                                               : 1.0;
    out.uncertainty(i) = pr.scales(i) * std::sqrt(v) * inflation;
    if (i < kNumBaseParameters)
      out.noise_only_ratio = std::max(out.noise_only_ratio,
                                      out.uncertainty(i) / (pr.scales(i) * std::sqrt(normal_inv(a, a))));
  }
  return out;
}

void ApplyScatter(const ScatterFit& scatter, FitSummary* fit) {
  fit->covariance = scatter.covariance;
  fit->uncertainty = scatter.uncertainty;
  fit->uncertainty_dof = scatter.dof;
  fit->uncertainty_scale = 1.0;
  ScatterModel m;
  const ScatterCandidate& c = scatter.candidates[static_cast<size_t>(scatter.chosen)];
  m.structure = c.structure;
  m.size = c.size;
  m.candidates = scatter.candidates;
  m.ratio_to_noise = scatter.noise_only_ratio;
  for (int i = 0; i < std::min<int>(kNumBaseParameters, static_cast<int>(scatter.dof.size())); ++i)
    if (std::isfinite(scatter.uncertainty(i)) && !(scatter.dof(i) >= m.min_dof)) m.min_dof = scatter.dof(i);
  fit->scatter = m;
}

std::string DescribeScatter(const ScatterModel& scatter) {
  switch (scatter.structure) {
    case ScatterStructure::kIndependent:
      return fmt::format("each capture off by its own amount (a scatter of {:.2g} counts per axis "
                         "between captures: handling, a pose not quite settled)", scatter.size);
    case ScatterStructure::kFlicker:
      return fmt::format("a bias that wanders like flicker noise (bias instability about {:.2g} "
                         "counts)", scatter.size);
    case ScatterStructure::kRandomWalk:
      return fmt::format("a bias that wanders like a random walk (about {:.2g} counts/sqrt(s), "
                         "{:.2g} counts from one minute to the next)", scatter.size,
                         scatter.size * std::sqrt(60.0));
  }
  return {};
}

}  // namespace accelcal
