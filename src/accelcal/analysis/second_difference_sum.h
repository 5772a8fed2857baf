// The inner sum of the overlapping Allan deviation (allan_deviation.h): sum over i < n of
// (x2[i] - 2 x1[i] + x0[i])^2, the squared second differences of the phase for n term starts.
// Four doubles at a time where the processor has AVX2 (chosen when the program runs), two
// (SSE2, Eigen's packets) otherwise; the two differ only in the order of the additions, at
// rounding level (issue 18: this sum is half of the Allan command's time).
#pragma once

#include <cstddef>

namespace accelcal::detail {

double SumSquaredSecondDifferences(const double* x0, const double* x1, const double* x2, size_t n);

}  // namespace accelcal::detail
