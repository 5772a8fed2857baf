// Weighted least squares over captures for any ResidualModel: NLopt (SLSQP with the analytic
// gradient) from the caller's initial guess, then a Gauss-Newton polish in Eigen that decides
// convergence and yields the covariance.
//
// Weights: sigma_i is the 1-sigma of capture i's residual from the uncertainty of its mean
// (sigma_i^2 = g^T Cov(mean) g, g = dr/d(mean raw)), plus, for a turntable run whose radius has
// an uncertainty of its own (a fixture's board off the plate's reference point), that radius's
// part (OwnRadiusSigma): an error that differs run to run scatters the residuals as noise does.
// It is evaluated at the initial guess for
// the NLopt stage and at NLopt's answer for the polish, then held fixed (it depends on the
// parameters only through the scales, weakly).
//
// Uncertainties: covariance = (J^T W J)^-1 (from the SVD of the weighted Jacobian), its sigmas
// multiplied by sqrt(max(1, chi2/dof)): when the residuals exceed what the noise explains, the
// noise-only covariance would claim more than the data support.
//
// Held parameters (options.held): a reduced model. They keep their value from `initial`, are not
// fitted, take no degree of freedom, and have no uncertainty (NaN in the summary; their rows and
// columns of the covariance are zero). An extended model keeps the base parameters' indices, so
// the diagnosis holds what the base fit held.
//
// Robustness: NLopt's answer is polished only when it is better than the initial guess (SLSQP
// can run off to 1e40 from a poor start); otherwise the polish starts from the guess. The
// polish refuses a numerically singular step (determinacy.h's relative criterion), naming the
// combination the captures do not determine.
#pragma once

#include <string>
#include <vector>

#include "accelcal/calibration/fit/determinacy.h"

#include <Eigen/Core>

#include "accelcal/calibration/fit/fit_capture.h"
#include "accelcal/calibration/fit/fit_summary.h"
#include "accelcal/calibration/fit/residual_model.h"

namespace accelcal {

struct LeastSquaresOptions {
  double gravity_mps2 = 9.80665;       // local gravity, m/s^2
  int max_evaluations = 5000;          // NLopt objective evaluations
  int max_gauss_newton_iterations = 100;
  // The polish has converged when no parameter moves by more than this fraction of its
  // ParameterScale (i.e. by 1e-3 * this, in m/s^2 of effect) in a step.
  double step_tolerance = 1e-6;
  // Above this condition number (column-equilibrated weighted Jacobian) a warning is issued.
  double condition_warning = 100.0;
  // Above this |rho| between two parameters a warning is issued.
  double correlation_warning = 0.995;
  // Parameters held at their initial value (indices into the model's parameter vector, each at
  // most once): not fitted. Empty: all are fitted.
  std::vector<int> held;
  // The initial guess is already close to the solution (the fit of nearly the same captures, as
  // in a leave-one-out refit): skip the NLopt stage and run the Gauss-Newton polish from it. The
  // polish converges to the same minimum by the same criterion; a polish that fails from there
  // ends the solve as any failed polish does (the caller may retry without warm_start).
  bool warm_start = false;

  std::string Validate() const;
};

// Solves from `initial` (size model.NumParameters()). Fills every field of the summary except
// `message`'s context, which the caller may prepend to. Never throws for numerical trouble:
// the termination says what happened.
FitSummary SolveWeightedLeastSquares(const ResidualModel& model,
                                     const std::vector<FitCapture>& captures,
                                     const Eigen::VectorXd& initial,
                                     const LeastSquaresOptions& options);

// The polish's convergence test of one Gauss-Newton step: converged when the step (infinity
// norm, in the scaled variables) is below options.step_tolerance, or when the cost (the sum of
// squared weighted residuals) no longer falls beyond round-off, cost -> new_cost (the cost after
// the step when it fell, else the cost itself), while the Gauss-Newton model predicts no more
// than a round-off decrease, `predicted` = |J step|^2. Shared with the leave-one-out update
// (diagnosis/leave_one_out.h), which must stop where a refit would.
bool IsGaussNewtonConverged(double step_size, double cost, double new_cost, double predicted,
                            const LeastSquaresOptions& options);

// sigma_i (m/s^2) of every capture's residual at p: its mean's uncertainty and, for a turntable
// run with one, its own radius uncertainty (OwnRadiusSigma), in quadrature.
Eigen::VectorXd ResidualSigmas(const ResidualModel& model, const std::vector<FitCapture>& captures,
                               const Eigen::VectorXd& p, double gravity_mps2);

// The part of a capture's residual sigma (m/s^2) that its own radius uncertainty gives
// (FitCapture::radius_own_u_m times |dr/d radius|); 0 for a static capture or a run without one.
double OwnRadiusSigma(const ResidualModel& model, const FitCapture& capture,
                      const Eigen::VectorXd& p, double gravity_mps2);

}  // namespace accelcal
