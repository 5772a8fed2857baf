// The common case of a number in a sample table, read exactly and fast: `[-]digits[.digits]
// [(e|E)[+-]digits]` with at most 19 digits in all and a value m * 10^e whose integer m is at
// most 2^53 and |e| at most 22 ("33096", "0.03987", "2.9840000e-02"). Then m and 10^e are exact
// doubles and one multiplication or division rounds correctly (Clinger's fast path, W. D.
// Clinger, "How to read floating point numbers accurately", PLDI 1990): the same double
// std::from_chars gives, at a fraction of its cost. Anything else (more digits, a larger
// exponent, hex, "inf", a malformed token) returns false and the caller uses std::from_chars,
// which also words the errors. Internal to src/.
#pragma once

#include <cstdint>

namespace accelcal::detail {

inline bool ScanSimpleDecimal(const char* p, const char* end, double* value) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                      1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                      1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  constexpr int kMaxDigits = 19;  // 10^19 - 1 < 2^64
  constexpr std::uint64_t kMaxExact = std::uint64_t{1} << 53;
  bool negative = false;
  if (p < end && *p == '-') {
    negative = true;
    ++p;
  }
  std::uint64_t m = 0;
  int digits = 0;
  const char* start = p;
  while (p < end && static_cast<unsigned>(*p - '0') < 10u) {
    m = m * 10 + static_cast<unsigned>(*p - '0');
    ++p;
  }
  digits = static_cast<int>(p - start);
  if (digits == 0) return false;
  int exponent = 0;
  if (p < end && *p == '.') {
    ++p;
    const char* frac = p;
    while (p < end && static_cast<unsigned>(*p - '0') < 10u) {
      m = m * 10 + static_cast<unsigned>(*p - '0');
      ++p;
    }
    const int frac_digits = static_cast<int>(p - frac);
    if (frac_digits == 0) return false;
    digits += frac_digits;
    exponent = -frac_digits;
  }
  if (digits > kMaxDigits) return false;  // m may have wrapped: let from_chars read it
  if (p < end && (*p == 'e' || *p == 'E')) {
    ++p;
    bool exp_negative = false;
    if (p < end && (*p == '+' || *p == '-')) exp_negative = *p++ == '-';
    const char* exp_start = p;
    int e = 0;
    while (p < end && static_cast<unsigned>(*p - '0') < 10u && p - exp_start < 4) {
      e = e * 10 + (*p - '0');
      ++p;
    }
    if (p == exp_start) return false;
    exponent += exp_negative ? -e : e;
  }
  if (p != end || m > kMaxExact || exponent < -22 || exponent > 22) return false;
  double v = static_cast<double>(m);
  v = exponent < 0 ? v / kPow10[-exponent] : v * kPow10[exponent];
  *value = negative ? -v : v;
  return true;
}

}  // namespace accelcal::detail
