// Leave-one-capture-out prediction: fit a model without each capture in turn and predict the
// capture it did not see. Judged against noise, not only ranked:
// each prediction error r_i is divided by what noise explains of it,
//
//   z_i = r_i / sqrt(sigma_i^2 + g_i^T C_(-i) g_i),
//
// sigma_i the capture's own 1-sigma, g_i = dr_i/dp and C_(-i) the noise-only covariance of the
// fit without it (the spread of the prediction itself). Under a right model and honest sigmas
// each z_i is a standard normal; an effect that explains the captures only by bending to each
// one predicts the left-out ones badly, and one capture that no model predicts is a capture
// that disagrees with the others (a mistyped radius, a wrong face).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "accelcal/calibration/fit/fit_capture.h"
#include "accelcal/calibration/fit/least_squares.h"
#include "accelcal/calibration/fit/residual_model.h"

namespace accelcal {

struct LeaveOneOutPrediction {
  int id = 0;                  // the capture's id
  double residual_mps2 = kNaN; // predicted |a^p| - reference, from the fit without it
  double z = kNaN;             // residual over its noise-only 1-sigma (header comment)
};

struct LeaveOneOutResult {
  std::vector<LeaveOneOutPrediction> predictions;  // one per capture, in input order
  double rms_mps2 = kNaN;      // RMS of the prediction errors
  double chi2 = kNaN;          // sum of z_i^2
  double worst_abs_z = kNaN;   // the largest |z_i|
  int worst_index = -1;        // its index in the captures
  int refitted = 0;            // captures whose fit without them needed a refit (header comment)
};

// The fit of `model` without each capture, from `p_full` (the fit of all of them): by the
// rank-one downdate of the full fit's normal equations (the exact leave-one-out step of a linear
// model), then Gauss-Newton steps with a Jacobian held, checked by a Jacobian evaluated where
// they settle: done when its step is below the polish's step tolerance (the polish's own test),
// so each capture costs a few evaluations of the residuals and one or two Jacobians. Where that
// does not apply (a capture of leverage above 0.999, a condition number above 1e6) or does not
// settle within 8 Jacobians, a refit: Gauss-Newton warm-started at p_full
// (LeastSquaresOptions::warm_start, at most 3 iterations), the full solve (NLopt, then
// Gauss-Newton) when that does not converge. A refit that fails both ways predicts from
// `p_full`. tests/unit/acquire/leave_one_out_test.cpp holds the result to cold refits.
LeaveOneOutResult PredictLeftOut(const ResidualModel& model, const std::vector<FitCapture>& captures,
                                 const Eigen::VectorXd& p_full, const LeastSquaresOptions& solver);

// The probability that the largest of n independent |N(0, 1)| exceeds |z| (the family-wise
// p-value of the worst prediction).
double WorstOfNormalsPValue(double abs_z, int n);

}  // namespace accelcal
