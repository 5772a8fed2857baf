// A weighted least-squares problem in the solver's variables (least_squares.h): only the free
// parameters vary, each in units of its ParameterScale at the anchor p0,
//   p = p0 + sum_k scales(free_k) x_k e_(free_k),
// and every capture's residual is weighted by its 1-sigma at p0, rho_i = r_i / sigma_i. Shared
// by the solver and the leave-one-out update (diagnosis/leave_one_out.h), which must take its
// steps in the same variables as the solver it stands in for.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "accelcal/calibration/fit/fit_capture.h"
#include "accelcal/calibration/fit/residual_model.h"

namespace accelcal {

struct ScaledProblem {
  const ResidualModel* model = nullptr;              // borrowed; outlives the problem
  const std::vector<FitCapture>* captures = nullptr;  // borrowed
  double gravity_mps2 = 0.0;
  Eigen::VectorXd p0;
  Eigen::VectorXd scales;  // of every parameter, at p0
  Eigen::VectorXd sigmas;  // of every capture's residual, at p0, m/s^2
  std::vector<int> free;   // indices of the fitted parameters

  int NumFree() const { return static_cast<int>(free.size()); }
  Eigen::VectorXd ToParameters(const double* x) const;
  Eigen::VectorXd ToParameters(const Eigen::VectorXd& x) const { return ToParameters(x.data()); }
  // A step in the scaled free variables, as a change of p.
  Eigen::VectorXd Step(const Eigen::VectorXd& x) const;
  // Moves the anchor to p: scales and sigmas taken there.
  void AnchorAt(const Eigen::VectorXd& p);
  // Weighted residuals rho_i = r_i / sigma_i at p and, with `jac`, their Jacobian in the scaled
  // free variables.
  void Evaluate(const Eigen::VectorXd& p, Eigen::VectorXd* rho, Eigen::MatrixXd* jac) const;
};

// The problem of `model` over `captures`, every parameter free but those in `held`, anchored at
// p0. A held index out of range, or twice, leaves fewer held than `held` names.
ScaledProblem MakeScaledProblem(const ResidualModel& model, const std::vector<FitCapture>& captures,
                                const Eigen::VectorXd& p0, const std::vector<int>& held,
                                double gravity_mps2);

}  // namespace accelcal
