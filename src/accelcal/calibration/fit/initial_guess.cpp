#include "accelcal/calibration/fit/initial_guess.h"

#include <cmath>

#include <Eigen/Dense>

#include "accelcal/base/linear_algebra.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal {
namespace {

double Reference(const FitCapture& c, double g) {
  return ReferenceMagnitudeMps2(c.kind, g, c.radius_m, c.rpm);
}

// Capture means centred and scaled to order one: raw counts squared reach 1e9 and would wreck
// the solves.
struct Normalized {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double spread = 0.0;
  Eigen::Vector3d Of(const Eigen::Vector3d& m) const { return (m - centre) / spread; }
};

Normalized Normalize(const std::vector<FitCapture>& captures) {
  Normalized n;
  const double count = static_cast<double>(captures.size());
  for (const FitCapture& c : captures) n.centre += c.mean_counts / count;
  for (const FitCapture& c : captures)
    n.spread = std::max(n.spread, (c.mean_counts - n.centre).cwiseAbs().maxCoeff());
  return n;
}

// The parameters of the axis-aligned ellipsoid sum_j A_j (m_j - c_j)^2 = G (scaled means)
// whose surface is |f| = g: k_j = sqrt(G / A_j) / g. False unless it is a real ellipsoid.
bool FromQuadric(const Eigen::Vector3d& a, const Eigen::Vector3d& c, double g_scaled, double g,
                 const Normalized& n, Eigen::VectorXd* p) {
  if (!(a.minCoeff() > 0.0) || !(g_scaled > 0.0)) return false;
  p->setZero(kNumBaseParameters);
  for (int j = 0; j < 3; ++j) {
    (*p)(kScaleX + j) = std::sqrt(g_scaled / a(j)) / g * n.spread;
    (*p)(kBiasX + j) = n.centre(j) + c(j) * n.spread;
  }
  return p->allFinite();
}

// Inhomogeneous: sum_j A_j m_j^2 - 2 B_j m_j + C = f^2, C free. Determined when the captures'
// references differ (turntable runs); for one reference (static poses alone) every member of
// a family of solutions fits as well, and noise picks one.
bool InhomogeneousGuess(const std::vector<FitCapture>& captures, double g, Eigen::VectorXd* p) {
  const int n = static_cast<int>(captures.size());
  if (n < 7) return false;
  const Normalized norm = Normalize(captures);
  if (!(norm.spread > 0.0)) return false;
  Eigen::MatrixXd a(n, 7);
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d m = norm.Of(captures[i].mean_counts);
    a.row(i) << m.x() * m.x(), m.y() * m.y(), m.z() * m.z(), -2.0 * m.x(), -2.0 * m.y(), -2.0 * m.z(), 1.0;
    const double f = Reference(captures[i], g);
    rhs(i) = f * f;
  }
  const Eigen::VectorXd sol = a.colPivHouseholderQr().solve(rhs);
  if (!sol.allFinite()) return false;
  const Eigen::Vector3d big_a = sol.head<3>();
  if (!(big_a.minCoeff() > 0.0)) return false;
  const Eigen::Vector3d c = sol.segment<3>(3).cwiseQuotient(big_a);
  // The surface in the scaled coordinates is sum A_j (m_j - c_j)^2 = g^2 by construction.
  return FromQuadric(big_a * (1.0 / (g * g)), c, 1.0, g, norm, p);
}

// Homogeneous, over the static captures: the quadric sum_j A_j m_j^2 - 2 B_j m_j + D = 0
// through their means (the right singular vector of the smallest singular value; six poses in
// general position determine it), its size then set by gravity. Immune to the family above.
bool StaticQuadricGuess(const std::vector<FitCapture>& captures, double g, Eigen::VectorXd* p) {
  std::vector<FitCapture> statics;
  for (const FitCapture& c : captures)
    if (c.kind == CaptureKind::kStatic) statics.push_back(c);
  const int n = static_cast<int>(statics.size());
  if (n < 6) return false;
  const Normalized norm = Normalize(statics);
  if (!(norm.spread > 0.0)) return false;
  Eigen::MatrixXd a(n, 7);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d m = norm.Of(statics[i].mean_counts);
    a.row(i) << m.x() * m.x(), m.y() * m.y(), m.z() * m.z(), -2.0 * m.x(), -2.0 * m.y(), -2.0 * m.z(), 1.0;
  }
  const SingularValueDecomposition svd = DecomposeSvd(a);
  Eigen::VectorXd v = svd.v.col(6);
  if (v.head<3>().sum() < 0.0) v = -v;
  const Eigen::Vector3d big_a = v.head<3>();
  if (!(big_a.minCoeff() > 0.0)) return false;
  const Eigen::Vector3d c = v.segment<3>(3).cwiseQuotient(big_a);
  const double g_scaled = v.segment<3>(3).cwiseProduct(c).sum() - v(6);  // sum B c - D
  return FromQuadric(big_a, c, g_scaled, g, norm, p);
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

// Sum of squared magnitude residuals, m/s^2 squared (infinite when undefined).
double Cost(const Eigen::VectorXd& p, const std::vector<FitCapture>& captures, double g) {
  const SensorModel model = SensorModel::FromVector(p);
  if (!model.Validate().empty()) return INFINITY;
  double sum = 0.0;
  for (const FitCapture& c : captures) {
    const double r = model.Calibrate(c.mean_counts).norm() - Reference(c, g);
    sum += r * r;
  }
  return std::isfinite(sum) ? sum : INFINITY;
}

}  // namespace

Eigen::VectorXd InitialGuess(const std::vector<FitCapture>& captures, double gravity_mps2,
                             std::string* how) {
  struct Candidate {
    const char* how;
    Eigen::VectorXd p;
    double cost = INFINITY;
  };
  std::vector<Candidate> candidates;
  Eigen::VectorXd p;
  if (StaticQuadricGuess(captures, gravity_mps2, &p))
    candidates.push_back({"axis-aligned ellipsoid through the static capture means, sized by gravity", p});
  if (InhomogeneousGuess(captures, gravity_mps2, &p))
    candidates.push_back({"axis-aligned ellipsoid through the capture means", p});
  candidates.push_back({"midpoint and spread of the capture means (no ellipsoid fits)",
                        SpreadGuess(captures, gravity_mps2)});
  size_t best = 0;
  for (size_t i = 0; i < candidates.size(); ++i) {
    candidates[i].cost = Cost(candidates[i].p, captures, gravity_mps2);
    if (candidates[i].cost < candidates[best].cost) best = i;
  }
  if (how != nullptr) *how = candidates[best].how;
  return candidates[best].p;
}

}  // namespace accelcal
