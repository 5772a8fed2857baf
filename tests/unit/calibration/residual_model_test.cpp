#include "accelcal/calibration/fit/residual_model.h"

#include <gtest/gtest.h>

namespace accelcal {
namespace {

// The analytic gradients must match central finite differences.
TEST(ResidualModel, GradientsMatchFiniteDifferences) {
  SensorModel m;
  m.bias_counts = {2051.3, 2037.8, 2069.2};
  m.scale_counts_per_mps2 = {34.91, 35.42, 34.17};
  m.a_yz_rad = 0.0042;
  m.a_zy_rad = -0.0061;
  m.a_zx_rad = 0.0027;
  const Eigen::VectorXd p = m.ToVector();
  FitCapture c;
  c.kind = CaptureKind::kTurntable;
  c.radius_m = 0.1;
  c.rpm = 120;
  c.mean_counts = m.Raw(Eigen::Vector3d(-4.0, 6.0, 7.5));
  const BaseResidualModel model;
  Eigen::VectorXd grad(9);
  Eigen::Vector3d grad_raw;
  model.Residual(p, c, 9.8, &grad, &grad_raw);
  for (int i = 0; i < 9; ++i) {
    const double h = model.ParameterScale(p, i);
    Eigen::VectorXd lo = p, hi = p;
    lo(i) -= h;
    hi(i) += h;
    const double fd = (model.Residual(hi, c, 9.8, nullptr, nullptr) -
                       model.Residual(lo, c, 9.8, nullptr, nullptr)) / (2 * h);
    EXPECT_NEAR(grad(i), fd, 1e-6 * std::max(1.0, std::fabs(fd))) << ParameterName(i);
  }
  for (int j = 0; j < 3; ++j) {
    FitCapture lo = c, hi = c;
    lo.mean_counts(j) -= 0.5;
    hi.mean_counts(j) += 0.5;
    const double fd = model.Residual(p, hi, 9.8, nullptr, nullptr) - model.Residual(p, lo, 9.8, nullptr, nullptr);
    EXPECT_NEAR(grad_raw(j), fd, 1e-5 * std::fabs(fd));
  }
}

}  // namespace
}  // namespace accelcal
