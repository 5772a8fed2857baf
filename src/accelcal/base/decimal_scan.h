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
#include <cstring>

namespace accelcal::detail {

// The count (0 to 8) of decimal digits at the start of the eight characters in v, loaded
// little-endian (the first character in the lowest byte). SWAR: a byte is a digit when its high
// nibble is 3 and its low nibble at most 9 (D. Lemire, "Fast parsing of floating-point
// numbers", 2021).
inline int LeadingDigits(std::uint64_t v) {
  const std::uint64_t non_digit = ((v ^ 0x3030303030303030ULL) & 0xF0F0F0F0F0F0F0F0ULL) |
                                  (((v & 0x0F0F0F0F0F0F0F0FULL) + 0x0606060606060606ULL) &
                                   0x1010101010101010ULL);
  return non_digit == 0 ? 8 : __builtin_ctzll(non_digit) / 8;
}

// The value of the digits of v that a left shift by `shift` bits keeps as the last ones (the
// shift 8 * (8 - n) keeps the first n, 1 to 8, with leading zeros), by pairs, quads and octets
// (Lemire's three multiplications).
inline std::uint64_t ShiftedDigitsValue(std::uint64_t v, int shift) {
  std::uint64_t d = (v << shift) & 0x0F0F0F0F0F0F0F0FULL;
  d = (d * 2561) >> 8;                                           // 10 * 2^8 + 1
  d = ((d & 0x00FF00FF00FF00FFULL) * 6553601) >> 16;             // 100 * 2^16 + 1
  return ((d & 0x0000FFFF0000FFFFULL) * 42949672960001) >> 32;  // 10000 * 2^32 + 1
}

// The value of the first n (1 to 8) digits of v (as LeadingDigits counted them).
inline std::uint64_t LeadingDigitsValue(std::uint64_t v, int n) {
  return ShiftedDigitsValue(v, 8 * (8 - n));
}

inline constexpr std::uint64_t kPow10Int[] = {1,      10,      100,      1000,     10000,
                                              100000, 1000000, 10000000, 100000000};
inline constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                    1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                    1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// Appends the run of decimal digits at p to m (m = 10 m + digit for each) and returns the first
// character after it: eight characters at a time while eight remain before `end`, byte by byte
// near the end. Overflow of m is the caller's to judge from the count of digits.
inline const char* ScanDigitRun(const char* p, const char* end, std::uint64_t* m) {
  std::uint64_t acc = *m;
  while (end - p >= 8) {
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    const int n = LeadingDigits(v);
    if (n == 0) break;
    acc = acc * kPow10Int[n] + LeadingDigitsValue(v, n);
    p += n;
    if (n < 8) {
      *m = acc;
      return p;
    }
  }
  while (p < end && static_cast<unsigned>(*p - '0') < 10u) {
    acc = acc * 10 + static_cast<unsigned>(*p - '0');
    ++p;
  }
  *m = acc;
  return p;
}

// The short form of that number, `[-]digits[.digits]` with 1 to 7 digits before the point and
// 1 to 7 after it ("2052", "-0.0398", "3599.999"), read from a buffer the caller guarantees
// readable for kShortDecimalReach characters from p: no bound is checked. Returns the character
// after the digits, with *value set to what ScanDecimalPrefix gives (m < 10^14 is exact, so one
// division by 10^k rounds correctly), or nullptr when the text does not start that way (no
// digit, eight digits or more on either side). The caller must then see a separator or the
// end of the line: anything else there ('e', a second '.', a letter) means the text was not a
// number in the short form after all.
inline constexpr long kShortDecimalReach = 18;  // the sign, then 8 + 1 + 8 bytes loaded at most
inline const char* ScanShortDecimal(const char* p, double* value) {
  const bool negative = *p == '-';
  if (negative) ++p;
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  const int int_digits = LeadingDigits(v);
  if (int_digits == 0 || int_digits == 8) return nullptr;
  std::uint64_t m = LeadingDigitsValue(v, int_digits);
  p += int_digits;
  double x;
  if (*p == '.') {
    std::memcpy(&v, p + 1, 8);
    const int frac_digits = LeadingDigits(v);
    if (frac_digits == 0 || frac_digits == 8) return nullptr;
    m = m * kPow10Int[frac_digits] + LeadingDigitsValue(v, frac_digits);
    x = static_cast<double>(m) / kPow10[frac_digits];
    p += 1 + frac_digits;
  } else {
    x = static_cast<double>(m);
  }
  *value = negative ? -x : x;
  return p;
}

// The longest prefix of [p, end) in that form: returns the character after it, with *value
// set, or nullptr when the text at p does not start with such a number (or it is not exact).
// The caller decides whether what follows may end a number.
inline const char* ScanDecimalPrefix(const char* p, const char* end, double* value) {
  constexpr int kMaxDigits = 19;  // 10^19 - 1 < 2^64
  constexpr std::uint64_t kMaxExact = std::uint64_t{1} << 53;
  bool negative = false;
  if (p < end && *p == '-') {
    negative = true;
    ++p;
  }
  std::uint64_t m = 0;
  const char* start = p;
  p = ScanDigitRun(p, end, &m);
  int digits = static_cast<int>(p - start);
  if (digits == 0) return nullptr;
  int exponent = 0;
  if (p < end && *p == '.') {
    ++p;
    const char* frac = p;
    p = ScanDigitRun(p, end, &m);
    const int frac_digits = static_cast<int>(p - frac);
    if (frac_digits == 0) return nullptr;
    digits += frac_digits;
    exponent = -frac_digits;
  }
  if (digits > kMaxDigits) return nullptr;  // m may have wrapped: let from_chars read it
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
    if (p == exp_start) return nullptr;
    exponent += exp_negative ? -e : e;
  }
  if (m > kMaxExact || exponent < -22 || exponent > 22) return nullptr;
  double v = static_cast<double>(m);
  v = exponent < 0 ? v / kPow10[-exponent] : v * kPow10[exponent];
  *value = negative ? -v : v;
  return p;
}

// True when all of [p, end) is such a number, read into *value.
inline bool ScanSimpleDecimal(const char* p, const char* end, double* value) {
  double v = 0.0;
  if (ScanDecimalPrefix(p, end, &v) != end) return false;
  *value = v;
  return true;
}

}  // namespace accelcal::detail
