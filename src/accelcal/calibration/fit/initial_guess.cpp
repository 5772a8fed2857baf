#include "accelcal/calibration/fit/initial_guess.h"

#include <cmath>

#include <Eigen/Dense>

#include "accelcal/base/sensor_model.h"

namespace accelcal {
namespace {

double Reference(const FitCapture& c, double g) {
  return ReferenceMagnitudeMps2(c.kind, g, c.radius_m, c.rpm);
}

// Returns false when the ellipsoid is not a real one.
bool EllipsoidGuess(const std::vector<FitCapture>& captures, double g, Eigen::VectorXd* p) {
  const int n = static_cast<int>(captures.size());
  if (n < 7) return false;
  // Centre and scale the means first: raw counts squared reach 1e9 and would wreck the solve.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const FitCapture& c : captures) centre += c.mean_counts / n;
  double spread = 0.0;
  for (const FitCapture& c : captures) spread = std::max(spread, (c.mean_counts - centre).cwiseAbs().maxCoeff());
  if (!(spread > 0.0)) return false;

  Eigen::MatrixXd a(n, 7);
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d m = (captures[i].mean_counts - centre) / spread;
    a.row(i) << m.x() * m.x(), m.y() * m.y(), m.z() * m.z(), -2.0 * m.x(), -2.0 * m.y(), -2.0 * m.z(), 1.0;
    const double f = Reference(captures[i], g);
    rhs(i) = f * f;
  }
  const Eigen::VectorXd sol = a.colPivHouseholderQr().solve(rhs);
  if (!sol.allFinite()) return false;
  p->setZero(kNumBaseParameters);
  for (int j = 0; j < 3; ++j) {
    if (!(sol(j) > 0.0)) return false;
    const double k_scaled = 1.0 / std::sqrt(sol(j));  // scaled units per m/s^2
    const double b_scaled = sol(3 + j) / sol(j);
    (*p)(kScaleX + j) = k_scaled * spread;
    (*p)(kBiasX + j) = centre(j) + b_scaled * spread;
  }
  return p->allFinite();
}

Eigen::VectorXd SpreadGuess(const std::vector<FitCapture>& captures, double g) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  double ref = 0.0;
  for (const FitCapture& c : captures) {
    lo = lo.cwiseMin(c.mean_counts);
    hi = hi.cwiseMax(c.mean_counts);
    ref = std::max(ref, Reference(c, g));
  }
  Eigen::VectorXd p = Eigen::VectorXd::Zero(kNumBaseParameters);
  for (int j = 0; j < 3; ++j) {
    p(kBiasX + j) = 0.5 * (lo(j) + hi(j));
    p(kScaleX + j) = std::max(0.5 * (hi(j) - lo(j)) / ref, 1e-9);
  }
  return p;
}

}  // namespace

Eigen::VectorXd InitialGuess(const std::vector<FitCapture>& captures, double gravity_mps2,
                             std::string* how) {
  Eigen::VectorXd p;
  if (EllipsoidGuess(captures, gravity_mps2, &p)) {
    if (how != nullptr) *how = "axis-aligned ellipsoid through the capture means";
    return p;
  }
  if (how != nullptr) *how = "midpoint and spread of the capture means (the ellipsoid fit failed)";
  return SpreadGuess(captures, gravity_mps2);
}

}  // namespace accelcal
