// A model of what a capture's calibrated magnitude should be, as a function of a parameter
// vector p. The base model (the seed's nine parameters) is one; models with added effects
// extend it. The fit minimizes sum_i (r_i / sigma_i)^2 over the captures.
//
// Conventions: p's first kNumBaseParameters entries are the base model's, in ParameterIndex
// order (sensor_model.h); residuals are in m/s^2, r = |a^p| - reference.
#pragma once

#include <string>

#include <Eigen/Core>

#include "accelcal/calibration/fit/fit_capture.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal {

class ResidualModel {
 public:
  virtual ~ResidualModel() = default;

  virtual int NumParameters() const = 0;
  // Name of parameter i (for reports and correlation messages).
  virtual std::string ParameterLabel(int i) const = 0;
  // Typical size of a change in parameter i that moves a residual by about 1 m/s^2 * 1e-3, in
  // the parameter's unit, given the current estimate. Used only to scale the optimizer's
  // variables so all are of order one.
  virtual double ParameterScale(const Eigen::VectorXd& p, int i) const = 0;

  // Residual of capture c (m/s^2) at p; when `grad_p` is not null, fills dr/dp (size
  // NumParameters()); when `grad_raw` is not null, fills dr/d(mean raw), per count (used to
  // propagate the mean's uncertainty into sigma_i).
  virtual double Residual(const Eigen::VectorXd& p, const FitCapture& c, double gravity_mps2,
                          Eigen::VectorXd* grad_p, Eigen::Vector3d* grad_raw) const = 0;
};

// The seed's model: r = |T K^-1 (mean - b)| - |f|, |f| = g or sqrt(g^2 + (w^2 r)^2).
class BaseResidualModel final : public ResidualModel {
 public:
  int NumParameters() const override { return kNumBaseParameters; }
  std::string ParameterLabel(int i) const override;
  double ParameterScale(const Eigen::VectorXd& p, int i) const override;
  double Residual(const Eigen::VectorXd& p, const FitCapture& c, double gravity_mps2,
                  Eigen::VectorXd* grad_p, Eigen::Vector3d* grad_raw) const override;
};

// |T K^-1 (raw - b)| and its derivatives with respect to the nine base parameters (written
// into the first 9 entries of grad_p when not null) and to raw (grad_raw when not null).
// Shared by every model built on the base one.
double CalibratedMagnitude(const Eigen::VectorXd& p, const Eigen::Vector3d& raw_counts,
                           Eigen::VectorXd* grad_p, Eigen::Vector3d* grad_raw);

}  // namespace accelcal
