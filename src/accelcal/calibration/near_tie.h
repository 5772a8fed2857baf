// Two effects the captures can barely tell apart (issue 29): the diagnosis adopts one, decided
// by the left-out prediction when its rival is 2 to 6 behind in BIC (diagnosis.h, step 3); such
// a choice is not strong evidence (Kass & Raftery: 6 or more is strong), and on the standard
// plan a quadratic can win over the cubic that is there and move bias_x by 7 sigma.
//
// "About equally": the rival passed every test of the guard in the round the adopted effect won
// and its BIC (on the round's shared residual scale) is less than 6 behind. Then
//   - both are named, with the BIC gap and the degrees of freedom left;
//   - the rival's model (the final set with the adopted effect replaced by the rival) is fitted
//     on the same captures, and the nine parameters' covariance gains d d^T / 4, d the rival's
//     nine less the adopted's: the variance of an equal mixture of the two answers, since these
//     captures do not say which is right;
//   - the capture that separates them is found among the six faces and each signed axis radial
//     at the session's largest radius and speed: the one the two models read most differently
//     (the difference of their residuals for the same reading, over a typical capture's sigma).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/calibration/diagnosis/diagnosis.h"
#include "accelcal/calibration/fit/calibration_fit.h"
#include "accelcal/calibration/fit/fit_capture.h"

namespace accelcal {

struct NearTie {
  std::string adopted;              // the effect adopted
  std::string rival;                // the one less than 6 behind
  double bic_gap = kNaN;            // rival's BIC less the adopted's (the round's scale), >= 0
  int dof_left = 0;                 // of the adopted's fit in that round
  Eigen::VectorXd parameter_shift;  // the nine: rival's fit less the adopted's final fit
  Eigen::VectorXd shift_sigmas;     // |shift| / the adopted's 1-sigma, per parameter
  std::string separating;           // the capture that tells them apart, in words
  double separation_sigmas = kNaN;  // how far apart they read it, in its sigma
};

// The near-ties of `diagnosis` over `captures` (the used ones, in the fit's order).
std::vector<NearTie> FindNearTies(const DiagnosisReport& diagnosis,
                                  const std::vector<FitCapture>& captures, const FitOptions& options);

// Widens the nine parameters' covariance and 1-sigma of `fit` by each tie's d d^T / 4.
void WidenForNearTies(const std::vector<NearTie>& ties, FitSummary* fit);

// "limited by a choice these captures cannot make: ..." for the verdict.
std::string NearTieWords(const NearTie& tie);

}  // namespace accelcal
