#include "accelcal/calibration/diagnosis/leave_one_out.h"

#include <cmath>

namespace accelcal {
namespace {

constexpr int kMaxWarmIterations = 3;  // Gauss-Newton iterations, the converging one included

}  // namespace

LeaveOneOutResult PredictLeftOut(const ResidualModel& model, const std::vector<FitCapture>& captures,
                                 const Eigen::VectorXd& p_full, const LeastSquaresOptions& solver) {
  LeaveOneOutResult out;
  const Eigen::VectorXd sigmas = ResidualSigmas(model, captures, p_full, solver.gravity_mps2);
  std::vector<FitCapture> rest;
  // Without one capture the minimum usually moves little from p_full: Gauss-Newton from there
  // reaches the same minimum as the full solve (by the same convergence test) at a fraction of
  // the cost. When it needs more than kMaxWarmIterations steps the capture moved the fit far
  // (a candidate model that bends to single captures): Gauss-Newton alone then sometimes stops
  // in a worse minimum than NLopt + Gauss-Newton (seen on the Xsens data: chi2 413 against
  // 401), so the full solve decides, as it does when the warm one fails.
  LeastSquaresOptions warm = solver;
  warm.warm_start = true;
  warm.max_gauss_newton_iterations = kMaxWarmIterations;  // not converged by then: not usable
  double sum_sq = 0.0, chi2 = 0.0;
  for (size_t i = 0; i < captures.size(); ++i) {
    rest.clear();
    for (size_t j = 0; j < captures.size(); ++j)
      if (j != i) rest.push_back(captures[j]);
    FitSummary s = SolveWeightedLeastSquares(model, rest, p_full, warm);
    if (!s.IsUsable()) s = SolveWeightedLeastSquares(model, rest, p_full, solver);
    const bool usable = s.IsUsable();
    const Eigen::VectorXd& p = usable ? s.parameters : p_full;
    Eigen::VectorXd grad(model.NumParameters());  // the base model writes it unsized
    const double r = model.Residual(p, captures[i], solver.gravity_mps2, &grad, nullptr);
    double var = sigmas(static_cast<Eigen::Index>(i)) * sigmas(static_cast<Eigen::Index>(i));
    if (usable && s.uncertainty_scale > 0.0) {
      // The fit's covariance carries the factor max(1, chi2/dof); the noise-only one does not.
      const double unscale = 1.0 / (s.uncertainty_scale * s.uncertainty_scale);
      var += unscale * grad.dot(s.covariance * grad);
    }
    LeaveOneOutPrediction pred{captures[i].id, r, r / std::sqrt(var)};
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
