// Reading the noise coefficients of an accelerometer axis off its Allan deviation curve, with the
// conventions of IEEE Std 952-1997 (Annex C; the same for accelerometers in IEEE Std 1293-2018):
//
//   noise density     N: the white-noise line, slope -1/2, sigma(tau) = N / sqrt(tau), read at
//   (velocity random  tau = 1 s. Unit: unit/sqrt(Hz) (= unit * sqrt(s)); for m/s^2, m/s/sqrt(s).
//    walk)            It is the continuous-time white-noise density Kalibr calls
//                     accelerometer_noise_density: a per-sample std sigma_d at rate f_s gives
//                     N = sigma_d / sqrt(f_s) (the two-sided PSD is N^2; a one-sided PSD is 2 N^2).
//   bias instability  B: the flat minimum of the curve divided by 0.664 = sqrt(2 ln 2 / pi), the
//                     flicker floor's level. Unit: unit. Reported with the tau of the minimum.
//   random walk       K: the rate-random-walk line, slope +1/2, sigma(tau) = K sqrt(tau / 3), read
//   (acceleration     at tau = 3 s. Unit: unit/sqrt(s) (for m/s^2, m/s^3/sqrt(Hz), Kalibr's
//    random walk)     accelerometer_random_walk).
//
// Where each line is read: the curve's local slope (least squares over +-0.25 decade) tells
// which term dominates each point; N is the edf-weighted (geometric) mean of sigma sqrt(tau)
// over the points of slope <= -0.3, K that of sqrt((sigma^2 - N^2/tau) 3 / tau) over the points
// of slope >= +0.3 (the white term, known, is taken off). A global fit of
// sigma^2 = N^2/tau + C + K^2 tau/3 was tried first and rejected: real flicker is not a
// constant over the decades where it and the other terms overlap, and the fit, dominated by
// the many-edf short taus, pushed K off by a factor of 3 on a simulated record. A term without
// its region is "not observed": the value given is the bound the curve's end allows (N from the
// first point, K from the last), and the notes say so.
#pragma once

#include <string>
#include <vector>

#include "accelcal/base/capture.h"  // kNaN

namespace accelcal {

struct AllanReadOffs {
  double noise_density = kNaN;           // N, unit/sqrt(Hz)
  double bias_instability = kNaN;        // B = min adev / 0.664, unit
  double bias_instability_tau_s = kNaN;  // tau of that minimum, s
  double random_walk = kNaN;             // K, unit/sqrt(s)
  bool white_noise_observed = false;     // the -1/2 term dominates somewhere in the range
  bool random_walk_observed = false;     // the +1/2 term dominates somewhere in the range
  bool minimum_is_interior = false;      // the minimum is not the curve's last point
  std::vector<std::string> notes;        // plain-language caveats for the user
};

// `tau_s` (increasing, > 0), `adev` (> 0) and `edf` (> 0; empty for equal weights) of one axis,
// all of the same length. Throws accelcal::Error when the lengths differ, fewer than 3 points,
// or a value is not finite or not positive.
AllanReadOffs ReadOffAllan(const std::vector<double>& tau_s, const std::vector<double>& adev,
                           const std::vector<double>& edf);

}  // namespace accelcal
