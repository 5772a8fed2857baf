// The chi-square distribution's upper tail, for asking "is this residual larger than noise?".
#pragma once

namespace accelcal {

// P(X >= chi2) for X ~ chi-square with `dof` degrees of freedom (the p-value of a chi-square
// test). Exact to ~1e-12 via the regularized upper incomplete gamma function Q(dof/2, chi2/2),
// evaluated by its power series below a + 1 and by Lentz's continued fraction above
// (Abramowitz & Stegun 6.5.29 and 6.5.31). Returns NaN for dof <= 0 or chi2 < 0.
double ChiSquareSurvival(double chi2, int dof);

}  // namespace accelcal
