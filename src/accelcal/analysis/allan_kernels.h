// The Allan deviation's inner loops (allan_deviation.h), four doubles at a time where the
// processor has AVX2 (chosen when the program runs), two (SSE2, Eigen's packets) otherwise; the
// two differ only in the order of the additions, at rounding level (issue 18: these sums are
// most of the Allan command's time beside reading the text).
#pragma once

#include <cstddef>

namespace accelcal::detail {

// Sum over i < n of (x2[i] - 2 x1[i] + x0[i])^2: the squared second differences of the phase
// for n term starts.
double SumSquaredSecondDifferences(const double* x0, const double* x1, const double* x2, size_t n);

// The lag-1 sums of a run of a series laid out with its previous value in front, s[0..k]:
// over i = 1 .. k, the sums of s[i], s[i]^2, s[i-1] and s[i-1] s[i] (zero for k = 0).
struct Lag1RunSums {
  double values = 0.0;
  double squares = 0.0;
  double earlier = 0.0;
  double products = 0.0;
};
Lag1RunSums SumLag1Run(const double* s, size_t k);

}  // namespace accelcal::detail
