// The chi-square distribution's upper tail, for asking "is this residual larger than noise?".
#pragma once

namespace accelcal {

// P(X >= chi2) for X ~ chi-square with `dof` degrees of freedom (the p-value of a chi-square
// test). Exact to ~1e-12 via the regularized upper incomplete gamma function Q(dof/2, chi2/2),
// evaluated by its power series below a + 1 and by Lentz's continued fraction above
// (Abramowitz & Stegun 6.5.29 and 6.5.31). Returns NaN for dof <= 0 or chi2 < 0.
double ChiSquareSurvival(double chi2, int dof);

// P(X <= chi2) for X ~ chi-square with a real, positive number of degrees of freedom (the
// equivalent degrees of freedom of a variance estimate are not integers). Same evaluation as
// above (the lower series is used directly below a + 1, so small probabilities keep their
// digits). Returns NaN for dof <= 0 or chi2 < 0 or a NaN argument.
double ChiSquareCdf(double chi2, double dof);

// The p-quantile: the chi2 with ChiSquareCdf(chi2, dof) == p, for 0 < p < 1 and dof > 0, to a
// relative 1e-13 (bracketing, then Newton steps safeguarded by bisection on the CDF above).
// Returns NaN outside that domain. Used for confidence bounds of variances:
// var * dof / ChiSquareQuantile(p, dof).
double ChiSquareQuantile(double p, double dof);

}  // namespace accelcal
