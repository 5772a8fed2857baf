// Is there structure left in a model's residuals? Noise is independent of everything the bench
// did; an effect the model lacks is not. Each capture's standardized residual z_i = r_i / sigma_i
// is correlated with what the bench varied from capture to capture:
//
//   time, and its square (a drift, a warm-up's curve); temperature; turntable or static; the
//   stated centripetal w^2 r; for each axis its loading u_j^2 and its sign u_j (direction cosines
//   through a rough model); and the corner product u_x u_y u_z.
//
// Each correlation's p-value (Fisher's z: atanh(rho) sqrt(n - 3) against a standard normal,
// two-sided) is corrected for the number of variables tested (Bonferroni). A variable that does
// not vary over the captures is not tested. A model's own fit leaves its residuals uncorrelated
// with what it already explains, so what is found here is what the model cannot absorb.
#pragma once

#include <string>
#include <vector>

#include "accelcal/calibration/fit/fit_capture.h"

namespace accelcal {

struct StructureFinding {
  std::string variable;     // "time", "temperature", "x loading (u_x^2)", ...
  double correlation = 0.0; // of the standardized residuals with it, -1..1
  double p_value = 1.0;     // single test, two-sided
};

struct ResidualStructure {
  std::vector<StructureFinding> tested;
  int strongest = -1;       // index of the smallest p-value in `tested`; -1 when none tested
  double family_p = 1.0;    // the smallest p-value times the number tested, at most 1

  // True when the strongest correlation is significant at family-wise level `alpha`.
  bool Found(double alpha) const { return strongest >= 0 && family_p < alpha; }
  // "the residuals follow time (correlation +0.81, p = 0.002 over 11 variables)"; empty when
  // nothing was tested.
  std::string Describe() const;
};

// `z` holds one standardized residual per capture (same order). At least 5 captures are needed
// to test anything.
ResidualStructure FindResidualStructure(const std::vector<FitCapture>& captures,
                                        const std::vector<double>& z);

}  // namespace accelcal
