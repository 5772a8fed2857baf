#include "accelcal/analysis/second_difference_sum.h"

#include <Eigen/Core>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define ACCELCAL_HAVE_AVX2_KERNEL 1
#endif

namespace accelcal::detail {
namespace {

double SumPortable(const double* x0, const double* x1, const double* x2, size_t n) {
  const auto len = static_cast<Eigen::Index>(n);
  Eigen::Map<const Eigen::ArrayXd> a0(x0, len), a1(x1, len), a2(x2, len);
  return (a2 - 2.0 * a1 + a0).square().sum();
}

#ifdef ACCELCAL_HAVE_AVX2_KERNEL
// Four accumulators of four lanes: the additions of one do not wait on another's.
__attribute__((target("avx2"))) double SumAvx2(const double* x0, const double* x1,
                                                 const double* x2, size_t n) {
  __m256d acc[4] = {_mm256_setzero_pd(), _mm256_setzero_pd(), _mm256_setzero_pd(),
                    _mm256_setzero_pd()};
  const __m256d two = _mm256_set1_pd(2.0);
  size_t i = 0;
  for (; i + 16 <= n; i += 16) {
    for (int k = 0; k < 4; ++k) {
      const size_t j = i + 4 * static_cast<size_t>(k);
      const __m256d d = _mm256_add_pd(
          _mm256_sub_pd(_mm256_loadu_pd(x2 + j), _mm256_mul_pd(two, _mm256_loadu_pd(x1 + j))),
          _mm256_loadu_pd(x0 + j));
      acc[k] = _mm256_add_pd(acc[k], _mm256_mul_pd(d, d));
    }
  }
  const __m256d sum4 = _mm256_add_pd(_mm256_add_pd(acc[0], acc[1]), _mm256_add_pd(acc[2], acc[3]));
  alignas(32) double lanes[4];
  _mm256_store_pd(lanes, sum4);
  double sum = (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]);
  for (; i < n; ++i) {
    const double d = x2[i] - 2.0 * x1[i] + x0[i];
    sum += d * d;
  }
  return sum;
}

bool HasAvx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}
#endif

}  // namespace

double SumSquaredSecondDifferences(const double* x0, const double* x1, const double* x2, size_t n) {
#ifdef ACCELCAL_HAVE_AVX2_KERNEL
  if (HasAvx2()) return SumAvx2(x0, x1, x2, n);
#endif
  return SumPortable(x0, x1, x2, n);
}

}  // namespace accelcal::detail
