// The uncertainty of a fit whose residuals exceed what the captures' own noise explains and no
// effect of the model explains them (issue 29): taken from the scatter between the captures, in
// a form that holds when that scatter is correlated in time.
//
// Scaling the covariance by sqrt(chi2/dof) assumes the excess is independent from capture to
// capture and shaped like the noise. A bias that wanders (a random walk, flicker noise) is
// neither: neighbouring captures share it, and the part that looks like the parameters (a common
// offset, a trend across the faces taken in a row) goes into them and out of the residuals. Here
// each capture's mean reading carries, besides its noise, an extra error of one of three
// structures, per axis and alike on the three axes (counts^2):
//
//   independent   C_ij = s^2 [i = j]: each capture off by its own amount (handling, a pose not
//                 quite settled), s in counts;
//   flicker       a bias wandering like 1/f noise: the variogram of the capture means
//                 E[(e_i - e_j)^2] = (4 / pi) B^2 ln(1 + |t_i - t_j| / T0), T0 = 10 s (for
//                 adjacent 10 s means that is twice the Allan variance 2 ln 2 B^2 / pi of flicker
//                 of instability B, IEEE Std 952-1997 C.1.4), B in counts;
//   random walk   a bias random walk: E[(e_i - e_j)^2] = K^2 |t_i - t_j|, K in counts/sqrt(s).
//
// The two that wander are stated by their variograms; their covariance is the double-centred
// -1/2 P G P (P = I - 11^T/n), i.e. each relative to its mean over the captures: a common offset
// is the bias itself, so the bias measured is the session's typical one (tests/physics defines its
// truth the same way). The residual r_i moves by g_i . e_i (g_i = dr_i / d mean_i), so the
// residuals' extra covariance is S_ij = (g_i . g_j) C_ij.
//
// Estimation: the fit's parameters stay those of the weighted least squares (the weights of the
// captures' noise, D = diag(sigma_i)); only their uncertainty changes. With the whitened
// Jacobian D^-1 J = Q1 R and Q2 the orthonormal complement of Q1, the error contrasts
// z = Q2^T D^-1 r have covariance I + lambda M, M = Q2^T D^-1 S D^-1 Q2: no parameter absorbs
// them, so the part of the wander that went into the parameters does not hide the wander's size.
// lambda (s^2, B^2 or K^2) is the restricted maximum likelihood (REML, Patterson & Thompson 1971)
// estimate over z; each structure is fitted, the one with the largest restricted likelihood is
// used (the three have one variance each, so the likelihoods compare directly). The parameters'
// covariance is the sandwich of the weighted least-squares estimator under that error model,
//   Cov(p) = (J^T W J)^-1 + lambda A S A^T,   A = (J^T W J)^-1 J^T W,  W = D^-2,
// and each parameter's effective degrees of freedom (Satterthwaite) come from the Fisher
// information of lambda: nu = 2 v^2 / (a^2 var(lambda)), v its variance, a its part per unit
// lambda. The stated 1-sigma is sqrt(v nu / (nu - 2)), the standard deviation of the
// t-distribution with nu degrees of freedom that the estimate follows (JCGM 101:2008 6.4.9.4,
// the scaled and shifted t of a Type A evaluation with few degrees of freedom), so that a
// 2-sigma interval keeps its coverage with nu near 9 (a plain t_9 gives 92 % at 2 sigma).
#pragma once

#include <string>
#include <vector>

#include "accelcal/calibration/fit/fit_capture.h"
#include "accelcal/calibration/fit/fit_summary.h"
#include "accelcal/calibration/fit/residual_model.h"

namespace accelcal {

struct ScatterUncertaintyOptions {
  // T0 of the flicker variogram, s (about a capture's length).
  double flicker_t0_s = 10.0;
};

// The result: empty `candidates` when it could not be computed (no degrees of freedom, captures
// without times for the structures in time: those are then skipped).
struct ScatterFit {
  std::vector<ScatterCandidate> candidates;  // every structure tried (fit_summary.h)
  int chosen = -1;                           // index into candidates; -1: none
  // Per parameter of the fit (its indices): the new 1-sigma (NaN where held) and effective dof.
  Eigen::VectorXd uncertainty;
  Eigen::VectorXd dof;
  Eigen::MatrixXd covariance;                // the sandwich, before the t-inflation
  double noise_only_ratio = 1.0;             // the largest u / u(noise only) over the nine
};

// Fits the structures to the residuals of `fit` (usable, of `model` over `captures`, in its
// order) and returns the uncertainty of the best one.
ScatterFit FitScatter(const ResidualModel& model, const std::vector<FitCapture>& captures,
                      const FitSummary& fit, const ScatterUncertaintyOptions& options = {});

// Puts `scatter` into `fit`: covariance, uncertainty (t-inflated), uncertainty_scale 1, and
// fit->scatter describing it. `scatter.chosen` must be >= 0.
void ApplyScatter(const ScatterFit& scatter, FitSummary* fit);

// The structure in words for the technician's printout: "a bias that wanders like a random
// walk, K = 0.061 counts/sqrt(s)".
std::string DescribeScatter(const ScatterModel& scatter);

}  // namespace accelcal
