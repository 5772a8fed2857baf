// Captures taken while the sensor was still settling after a change of pose (issue 29).
//
// The physics: a share of a MEMS accelerometer's response lags its input (the anelastic
// after-effect of the package, the mount's creep): after a change of pose the reading relaxes
// from where it was toward its new value with a time constant tau of seconds to a minute. A
// capture that starts before that is done carries an offset toward the previous pose's reading,
// decaying inside it,
//   x_ij(t) = m_ij + A_ij exp(-(t - t0_i) / tau) + noise,   A_ij = c_j D_ij,
// with t0_i the capture's first sample, m_ij the settled reading (what the fit wants), D_ij the
// previous capture's mean reading less this one's (the change of pose on axis j, counts) and c_j
// the share still lagging when the capture starts (eps_j exp(-lead/tau), alike from capture to
// capture when the handling is). Its mean is off by A_ij e_i, e_i the mean of the exponential
// over the capture's samples: on the faces taken in a row that offset always points back to
// the previous face, so the scales come out small by several sigmas (the issue measured 2.6-3.6).
//
// Detection: for each tau of a grid (2 s to 1 min), every capture's samples are fitted by a
// constant and the exponential (and a turntable run's once-per-revolution swing at its stated
// speed), giving A_ij with its noise-only variance; then, per axis, A_ij is regressed on D_ij
// over the captures (weighted by those variances, the scatter about the line estimated from the
// captures themselves, at least the noise's), and the t-statistic of c_j tested. The tau with the
// largest statistic is the settling time measured (a coarse figure: on 10 s captures taus of
// 10 to 60 s look alike). A wander of the bias (random walk, flicker)
// puts trends into the captures too, but they do not follow D_ij: their extra scatter goes into
// the regression's own scatter and not into c_j. A drift or a warm-up common to all captures
// is taken out first (each axis less the pooled slope inside the captures: the means stay, for
// the fit's drift and temperature effects).
//
// Handling: when the c_j are significant (sum over the axes of t_j^2, against chi-square with 3
// dof widened for the t's own dof, at `significance` after the look at the tau grid), every
// capture's reading becomes its settled value, m_ij = mean_ij - c_j D_ij e_i, and its mean's variance gains (D_ij e_i)^2 var(c_j). The
// capture is not left out: the settled value is what a longer wait would have read.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"

namespace accelcal {

struct SettlingOptions {
  double min_tau_s = 2.0;    // the shortest settling time tried, s
  double max_tau_s = 60.0;   // the longest, s (beyond, a 10 s capture sees a straight line)
  int tau_steps = 25;        // log-spaced
  // Chance of calling clean captures settling (the family of taus).
  double significance = 1e-3;
  // Fewest captures with a change of pose to judge; below it nothing is done.
  int min_captures = 5;
};

// What was found. `detected` false: the captures are untouched.
struct SettlingFinding {
  bool detected = false;
  double tau_s = kNaN;                                // the settling time measured, s
  Eigen::Vector3d lag_share = Eigen::Vector3d::Zero(); // c_j: share of a change still lagging
  Eigen::Vector3d t_statistic = Eigen::Vector3d::Zero();  // of c_j, per axis, at tau_s
  double critical_score = kNaN;                       // sum of t_j^2 beyond which it is settling
  int captures = 0;                                   // captures judged
  // The capture with the largest offset of its mean (counts, the largest axis) and its label.
  double largest_offset_counts = 0.0;
  std::string largest_offset_label;
};

// Judges the used captures (static and turntable runs, in time order); when they were still
// settling, sets Capture::settled on each (the fit then uses the settled reading).
SettlingFinding HandleSettling(std::vector<Capture>& captures, const SettlingOptions& options = {});

// The sentence for the verdict ("limited by ..."): what was seen, what was done, how long to wait.
std::string SettlingWords(const SettlingFinding& finding);

}  // namespace accelcal
