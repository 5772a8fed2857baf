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
// N and K are the coefficients of a weighted least-squares fit of the whole curve to
// sigma^2(tau) = N^2/tau + C + K^2 tau / 3 (IEEE 952 Annex C.2 fits such a sum of power terms),
// all coefficients >= 0, each point weighted by its equivalent degrees of freedom (the variance of
// an Allan variance estimate is ~ 2 sigma^4 / edf): the lines' values at tau = 1 s and 3 s
// without having to pick the slope regions by eye. A term is "observed" when it is the largest
// of the three somewhere in the curve's tau range; otherwise its coefficient is only what the
// fit could not rule out, and the result says so.
#pragma once

#include <string>
#include <vector>

#include "accelcal/capture.h"  // kNaN

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
