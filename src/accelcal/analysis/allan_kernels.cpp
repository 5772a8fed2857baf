#include "accelcal/analysis/allan_kernels.h"

#include <Eigen/Core>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define ACCELCAL_HAVE_AVX2_KERNELS 1
#endif

namespace accelcal::detail {
namespace {

double SumSecondPortable(const double* x0, const double* x1, const double* x2, size_t n) {
  const auto len = static_cast<Eigen::Index>(n);
  Eigen::Map<const Eigen::ArrayXd> a0(x0, len), a1(x1, len), a2(x2, len);
  return (a2 - 2.0 * a1 + a0).square().sum();
}

Lag1RunSums SumLag1Portable(const double* s, size_t k) {
  const auto len = static_cast<Eigen::Index>(k);
  Eigen::Map<const Eigen::ArrayXd> earlier(s, len), later(s + 1, len);
  return {later.sum(), later.square().sum(), earlier.sum(), (earlier * later).sum()};
}

#ifdef ACCELCAL_HAVE_AVX2_KERNELS
__attribute__((target("avx2"))) double HorizontalSum(__m256d v) {
  alignas(32) double lanes[4];
  _mm256_store_pd(lanes, v);
  return (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]);
}

// Four accumulators of four lanes: the additions of one do not wait on another's.
__attribute__((target("avx2"))) double SumSecondAvx2(const double* x0, const double* x1,
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
  double sum = HorizontalSum(_mm256_add_pd(_mm256_add_pd(acc[0], acc[1]), _mm256_add_pd(acc[2], acc[3])));
  for (; i < n; ++i) {
    const double d = x2[i] - 2.0 * x1[i] + x0[i];
    sum += d * d;
  }
  return sum;
}

// The four sums in one pass (Eigen's take four).
__attribute__((target("avx2"))) Lag1RunSums SumLag1Avx2(const double* s, size_t k) {
  __m256d values = _mm256_setzero_pd(), squares = _mm256_setzero_pd();
  __m256d earlier = _mm256_setzero_pd(), products = _mm256_setzero_pd();
  size_t i = 0;
  for (; i + 4 <= k; i += 4) {
    const __m256d a = _mm256_loadu_pd(s + i);
    const __m256d b = _mm256_loadu_pd(s + i + 1);
    values = _mm256_add_pd(values, b);
    squares = _mm256_add_pd(squares, _mm256_mul_pd(b, b));
    earlier = _mm256_add_pd(earlier, a);
    products = _mm256_add_pd(products, _mm256_mul_pd(a, b));
  }
  Lag1RunSums r{HorizontalSum(values), HorizontalSum(squares), HorizontalSum(earlier),
                HorizontalSum(products)};
  for (; i < k; ++i) {
    r.values += s[i + 1];
    r.squares += s[i + 1] * s[i + 1];
    r.earlier += s[i];
    r.products += s[i] * s[i + 1];
  }
  return r;
}

bool HasAvx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}
#endif

}  // namespace

double SumSquaredSecondDifferences(const double* x0, const double* x1, const double* x2, size_t n) {
#ifdef ACCELCAL_HAVE_AVX2_KERNELS
  if (HasAvx2()) return SumSecondAvx2(x0, x1, x2, n);
#endif
  return SumSecondPortable(x0, x1, x2, n);
}

Lag1RunSums SumLag1Run(const double* s, size_t k) {
#ifdef ACCELCAL_HAVE_AVX2_KERNELS
  if (HasAvx2()) return SumLag1Avx2(s, k);
#endif
  return SumLag1Portable(s, k);
}

}  // namespace accelcal::detail
