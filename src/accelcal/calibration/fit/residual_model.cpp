#include "accelcal/calibration/fit/residual_model.h"

#include <cmath>

namespace accelcal {

double CalibratedMagnitude(const Eigen::VectorXd& p, const Eigen::Vector3d& raw_counts,
                           Eigen::VectorXd* grad_p, Eigen::Vector3d* grad_raw) {
  const Eigen::Vector3d b = p.segment<3>(kBiasX);
  const Eigen::Vector3d k = p.segment<3>(kScaleX);
  const double a_yz = p(kMisYZ), a_zy = p(kMisZY), a_zx = p(kMisZX);
  const Eigen::Vector3d u = (raw_counts - b).cwiseQuotient(k);  // a^a, m/s^2
  const Eigen::Vector3d a(u.x() - a_yz * u.y() + a_zy * u.z(),   // a^p = T u
                          u.y() - a_zx * u.z(),
                          u.z());
  const double norm = a.norm();
  if (grad_p == nullptr && grad_raw == nullptr) return norm;

  const Eigen::Vector3d n = a / norm;  // d|a|/da
  // d|a|/du = T^T n.
  const Eigen::Vector3d tn(n.x(), -a_yz * n.x() + n.y(), a_zy * n.x() - a_zx * n.y() + n.z());
  if (grad_raw != nullptr) *grad_raw = tn.cwiseQuotient(k);
  if (grad_p != nullptr) {
    Eigen::VectorXd& g = *grad_p;
    for (int j = 0; j < 3; ++j) {
      g(kBiasX + j) = -tn(j) / k(j);
      g(kScaleX + j) = -tn(j) * u(j) / k(j);
    }
    g(kMisYZ) = -n.x() * u.y();
    g(kMisZY) = n.x() * u.z();
    g(kMisZX) = -n.y() * u.z();
  }
  return norm;
}

std::string BaseResidualModel::ParameterLabel(int i) const { return std::string(ParameterName(i)); }

double BaseResidualModel::ParameterScale(const Eigen::VectorXd& p, int i) const {
  // 1e-3 m/s^2 of bias is k * 1e-3 counts; 1e-3 relative scale is k * 1e-3; angles 1e-3 rad.
  if (i <= kBiasZ) return std::fabs(p(kScaleX + i)) * 1e-3;
  if (i <= kScaleZ) return std::fabs(p(i)) * 1e-3;
  return 1e-3;
}

double BaseResidualModel::Residual(const Eigen::VectorXd& p, const FitCapture& c,
                                   double gravity_mps2, Eigen::VectorXd* grad_p,
                                   Eigen::Vector3d* grad_raw) const {
  const double reference = ReferenceMagnitudeMps2(c.kind, gravity_mps2, c.radius_m, c.rpm);
  return CalibratedMagnitude(p, c.mean_counts, grad_p, grad_raw) - reference;
}

}  // namespace accelcal
