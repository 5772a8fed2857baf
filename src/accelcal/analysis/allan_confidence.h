// Confidence intervals of the (overlapping) Allan deviation: power-law noise identification,
// equivalent degrees of freedom (EDF) and chi-square bounds, as Stable32 computes them.
//
// Conventions:
//   - alpha is the exponent of the frequency-noise spectrum S_y(f) ~ f^alpha: +2 white PM,
//     +1 flicker PM, 0 white FM, -1 flicker FM, -2 random-walk FM. For an accelerometer read as
//     "frequency-type" data, white FM is velocity random walk (white acceleration noise),
//     flicker FM is bias instability and random-walk FM is acceleration random walk.
//   - m is the averaging factor (tau = m * tau0); series are frequency-type (one reading per
//     sample), the m-averaged series z_k is the mean of readings k*m .. k*m + m - 1.
//
// Sources:
//   - EDF: C. A. Greenhall and W. J. Riley, "Uncertainty of stability variances based on finite
//     differences", Proc. 35th PTTI (2003): equations (7)-(10) and its tables 2 and 3
//     (implemented here for d = 2, unmodified, with a stride factor S).
//   - Noise identification: W. J. Riley and C. A. Greenhall, "Power law noise identification
//     using the lag 1 autocorrelation", Proc. 18th EFTF (2004); when there are fewer than
//     kLag1MinPoints averages, the B1 ratio of D. W. Allan and J. A. Barnes / NIST SP 1065
//     (Riley, "Handbook of Frequency Stability Analysis", 2008, section 5.6) with R(n) to tell
//     white from flicker PM.
//   - Bounds: NIST SP 1065 eq. (45), sigma * sqrt(edf / chi2_p(edf)).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace accelcal {

// How the alpha of a point was found.
enum class NoiseIdMethod {
  kNone,        // too few averages (fewer than 2): alpha assumed 0 (white FM)
  kLag1Acf,     // lag-1 autocorrelation (at least kLag1MinPoints averages)
  kB1Ratio,     // B1 ratio (and, for B1's PM answer, R(n) or its streaming stand-in)
};
std::string NoiseIdMethodToString(NoiseIdMethod method);

// Averages needed for the lag-1 autocorrelation method (Riley & Greenhall 2004 recommend ~30).
inline constexpr int64_t kLag1MinPoints = 30;

// The lag-1 autocorrelation of a series w_0 .. w_{n-1} about its mean, normalised as Stable32
// does: r1 = [(1/n) sum_{k<n-1} (w_k - mean)(w_{k+1} - mean)] / [(1/(n-1)) sum_k (w_k - mean)^2].
// (Riley & Greenhall's eq. 2 has 1/n in both; this normalisation, with no drift removal, is the
// one that reproduces Stable32's alpha at all 167 lag-1 points of the reference tables, where
// the paper's reproduces 164.) NaN for n < 2 or a constant series.
double Lag1Autocorrelation(std::span<const double> w);

// r1 of the m-averaged series z after d = 0, 1, 2 first differences, as the method needs them.
std::array<double, 3> Lag1Autocorrelations(std::span<const double> z);

// Riley & Greenhall's decision from those: the first d (0, 1 or 2) with
// delta = r1 / (1 + r1) < 0.25 (or d = 2), then alpha = -round(2 delta) - 2 d, limited to
// [-2, 2] (the range the Allan variance distinguishes). 0 if r1 is undefined (constant data).
int Lag1NoiseAlpha(const std::array<double, 3>& r1);

// Noise from the B1 ratio b1 = (variance of the m-averaged series, divided by its length n) /
// (the Allan variance at m of the estimate being made), with n_avg = N / m (real) in Barnes'
// B1(N, mu) = N (1 - N^mu) / (2 (N-1)(1 - 2^mu)): the mu in {-2, -1, 0, 1} whose interval
// (bounded by geometric means of neighbouring B1 values) holds b1, mapped mu = 1, 0, -1 to
// alpha = -2, -1, 0. mu = -2 (white or flicker PM) returns 2; the caller resolves it with
// ResolvePhaseNoise. (These normalisations are the ones that reproduce Stable32 best on the
// reference tables: 93 of the 106 points with fewer than 30 averages; see the test.)
int B1NoiseAlpha(double b1, double n_avg);

// White (2) or flicker (1) PM from R(n) = Mod-AVAR / AVAR at averaging factor m: the theoretical
// R(n) is 1/m for white PM and, for flicker PM with a bandwidth f_h = 1/(2 tau0),
// 3 ln(256/27) / (8 pi^2) divided by (1.038 + 3 ln(pi m)) / (4 pi^2) (NIST SP 1065 table 3 and
// section 5.2.5); the boundary is their geometric mean.
int ResolvePhaseNoise(double rn, int64_t m);

// Greenhall-Riley EDF of the Allan variance (d = 2, unmodified) at averaging factor m for a
// record of `phase_points` phase points (frequency readings + 1), estimated with terms every
// `stride` samples (1 fully overlapping, m non-overlapping; stride must divide m).
// alpha in [-2, 2]. Returns NaN when there is not a single term.
double AllanEdf(int alpha, int64_t m, int64_t stride, int64_t phase_points);

// How the chi-square quantiles of the bounds are computed.
enum class ChiSquareMethod {
  kExact,     // the quantile of the chi-square distribution (diagnosis/chi_square.h)
  kStable32,  // as Stable32 1.60: exact up to 100 degrees of freedom, above that Abramowitz &
              // Stegun 26.4.17 (Wilson-Hilferty) with the normal quantile from A&S 26.2.22 and
              // Stable32's coefficient a1 = 0.27601 (A&S prints 0.27061), as documented by
              // A. Wallin, "Fun with Chi-Squared" (2020). Bounds then differ from kExact by up
              // to ~1e-3 relative for edf just above 100; use it to compare with Stable32.
};

// The one-sigma probability erf(1/sqrt 2) that Stable32 labels "0.683".
inline constexpr double kOneSigmaConfidence = 0.68268949213708585;

struct DeviationBounds {
  double lo = 0.0;  // same unit as the deviation
  double hi = 0.0;
};
// Two-sided bounds with probability `confidence` of a deviation with `edf` equivalent degrees
// of freedom: dev * sqrt(edf / chi2_{(1 +- confidence)/2}(edf)).
DeviationBounds ChiSquareDeviationBounds(double dev, double edf, double confidence,
                                         ChiSquareMethod method = ChiSquareMethod::kExact);

}  // namespace accelcal
