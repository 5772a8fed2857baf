#include "accelcal/calibration/fit/scaled_problem.h"

#include <algorithm>

#include "accelcal/calibration/fit/least_squares.h"

namespace accelcal {

Eigen::VectorXd ScaledProblem::ToParameters(const double* x) const {
  Eigen::VectorXd p = p0;
  for (int k = 0; k < NumFree(); ++k) p(free[k]) += scales(free[k]) * x[k];
  return p;
}

Eigen::VectorXd ScaledProblem::Step(const Eigen::VectorXd& x) const {
  Eigen::VectorXd d = Eigen::VectorXd::Zero(p0.size());
  for (int k = 0; k < NumFree(); ++k) d(free[k]) = scales(free[k]) * x(k);
  return d;
}

void ScaledProblem::AnchorAt(const Eigen::VectorXd& p) {
  p0 = p;
  scales.resize(p.size());
  for (int i = 0; i < p.size(); ++i) scales(i) = model->ParameterScale(p, i);
  sigmas = ResidualSigmas(*model, *captures, p, gravity_mps2);
}

void ScaledProblem::Evaluate(const Eigen::VectorXd& p, Eigen::VectorXd* rho,
                             Eigen::MatrixXd* jac) const {
  const int n = static_cast<int>(captures->size());
  const int np = static_cast<int>(p.size());
  rho->resize(n);
  if (jac != nullptr) jac->resize(n, NumFree());
  Eigen::VectorXd grad(np);
  for (int i = 0; i < n; ++i) {
    const double r = model->Residual(p, (*captures)[i], gravity_mps2,
                                     jac != nullptr ? &grad : nullptr, nullptr);
    (*rho)(i) = r / sigmas(i);
    if (jac != nullptr) {
      for (int k = 0; k < NumFree(); ++k)
        (*jac)(i, k) = grad(free[k]) * scales(free[k]) / sigmas(i);
    }
  }
}

ScaledProblem MakeScaledProblem(const ResidualModel& model, const std::vector<FitCapture>& captures,
                                const Eigen::VectorXd& p0, const std::vector<int>& held,
                                double gravity_mps2) {
  ScaledProblem pr;
  pr.model = &model;
  pr.captures = &captures;
  pr.gravity_mps2 = gravity_mps2;
  for (int i = 0; i < p0.size(); ++i)
    if (std::find(held.begin(), held.end(), i) == held.end()) pr.free.push_back(i);
  pr.AnchorAt(p0);
  return pr;
}

}  // namespace accelcal
