// Student's t-distribution, for the coverage factor of an expanded uncertainty (GUM, JCGM
// 100:2008, annex G): k = t_p(nu_eff), the two-sided p-quantile with the effective degrees of
// freedom of the combined uncertainty.
#pragma once

namespace accelcal {

// The coverage probability the GUM's k = 2 corresponds to for a normal distribution (G.1.3).
inline constexpr double kCoverageProbability = 0.9545;

// The two-sided coverage factor: the t with P(|T| <= t) = p for T ~ Student's t with `dof`
// degrees of freedom (real, > 0; +infinity gives the normal distribution's), 0 < p < 1. The
// CDF is the integral of the density (composite Simpson on 0..t, whose error is far below what
// a coverage factor needs), inverted by bisection to 1e-9. NaN outside the domain.
double StudentTCoverageFactor(double p, double dof);

}  // namespace accelcal
