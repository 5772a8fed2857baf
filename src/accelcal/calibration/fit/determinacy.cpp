#include "accelcal/calibration/fit/determinacy.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/base/linear_algebra.h"
#include "accelcal/calibration/fit/least_squares.h"

namespace accelcal {

Determinacy JudgeDeterminacy(const ResidualModel& model, const std::vector<FitCapture>& captures,
                             const Eigen::VectorXd& p, const DeterminacyOptions& options) {
  const int np = model.NumParameters();
  std::vector<int> free;
  for (int j = 0; j < np; ++j)
    if (std::find(options.held.begin(), options.held.end(), j) == options.held.end()) free.push_back(j);
  const int nf = static_cast<int>(free.size());
  const int n = static_cast<int>(captures.size());
  Determinacy out;
  if (nf == 0) return out;

  const Eigen::VectorXd sigmas = ResidualSigmas(model, captures, p, options.gravity_mps2);
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(std::max(n, nf), nf);  // zero rows: fewer captures
  Eigen::VectorXd grad(np);
  for (int i = 0; i < n; ++i) {
    model.Residual(p, captures[static_cast<size_t>(i)], options.gravity_mps2, &grad, nullptr);
    for (int k = 0; k < nf; ++k)
      jac(i, k) = grad(free[static_cast<size_t>(k)]) * model.ParameterScale(p, free[static_cast<size_t>(k)]) / sigmas(i);
  }
  const SingularValueDecomposition svd = DecomposeSvd(jac);
  const double s_max = svd.values.size() > 0 ? svd.values(0) : 0.0;
  for (int k = 0; k < nf; ++k) {
    const double s = svd.values(k);
    const double sigma = s > 0.0 && std::isfinite(s) ? 1.0 / s : INFINITY;
    out.worst_sigma_scaled = std::max(out.worst_sigma_scaled, sigma);
    const bool singular = !(s > options.min_relative_singular_value * s_max);
    if (!singular && sigma <= options.max_sigma_scaled) continue;
    UndeterminedCombination u;
    u.direction = Eigen::VectorXd::Zero(np);
    for (int f = 0; f < nf; ++f) u.direction(free[static_cast<size_t>(f)]) = svd.v(f, k);
    u.sigma_scaled = singular ? INFINITY : sigma;
    out.undetermined.push_back(std::move(u));
  }
  return out;
}

std::string DescribeCombination(const ResidualModel& model, const Eigen::VectorXd& direction) {
  std::vector<int> order;
  for (int j = 0; j < direction.size(); ++j)
    if (std::fabs(direction(j)) >= 0.1) order.push_back(j);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return std::fabs(direction(a)) > std::fabs(direction(b)); });
  // Signs relative to the largest term.
  const double sign = order.empty() || direction(order.front()) >= 0.0 ? 1.0 : -1.0;
  std::string names, terms;
  for (int j : order) {
    names += (names.empty() ? "" : ", ") + model.ParameterLabel(j);
    const double w = sign * direction(j);
    terms += terms.empty() ? fmt::format("{:.2f} {}", w, model.ParameterLabel(j))
                           : fmt::format(" {} {:.2f} {}", w < 0 ? '-' : '+', std::fabs(w),
                                         model.ParameterLabel(j));
  }
  if (order.size() <= 1) return names;
  return fmt::format("{} (the combination {})", names, terms);
}

}  // namespace accelcal
