#include "accelcal/base/line_shapes.h"

#include <cstring>

#include "accelcal/base/decimal_scan.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace accelcal::detail {

#if defined(__SSE2__)

namespace {

bool IsDigit(char c) { return static_cast<unsigned>(c - '0') < 10u; }

std::uint64_t Load8(const char* p) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  return v;
}

// A set from the places of the digits in a line's first 16 bytes (Fibonacci hashing).
int SetOf(std::uint32_t digit_bits) {
  static_assert(LineShapes::kSets == 16);
  return static_cast<int>((digit_bits * 0x9E3779B1u) >> 28);
}

// The value of a number whose digits are where `n` says, as ScanShortDecimal computes it (m
// below 10^14 converts exactly as a signed integer).
__attribute__((always_inline)) inline double ValueAt(const char* line, const auto& n) {
  std::uint64_t m = ShiftedDigitsValue(Load8(line + n.digits_at), n.digits_shift);
  double x;
  if (n.fraction > 0) {
    m = m * kPow10Int[n.fraction] +
        ShiftedDigitsValue(Load8(line + n.fraction_at), n.fraction_shift);
    x = static_cast<double>(static_cast<std::int64_t>(m)) / kPow10[n.fraction];
  } else {
    x = static_cast<double>(static_cast<std::int64_t>(m));
  }
  return x * n.sign;
}

// The numbers of a line of `shape`, kFields of them (a loop the compiler unrolls).
template <int kFields, class Shape>
void ValuesAt(const char* line, const Shape& shape, double* values) {
  for (int f = 0; f < kFields; ++f)
    values[f] = ValueAt(line, shape.numbers[static_cast<size_t>(f)]);
}

// The 16 bytes at p with each digit replaced by '0', and (in *digit_bits) which were digits.
__m128i ClassesOf(const char* p, std::uint32_t* digit_bits) {
  const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
  const __m128i above_zero = _mm_sub_epi8(bytes, _mm_set1_epi8('0'));
  const __m128i digit = _mm_cmpeq_epi8(_mm_min_epu8(above_zero, _mm_set1_epi8(9)), above_zero);
  *digit_bits = static_cast<std::uint32_t>(_mm_movemask_epi8(digit));
  return _mm_or_si128(_mm_and_si128(digit, _mm_set1_epi8('0')), _mm_andnot_si128(digit, bytes));
}

}  // namespace

// Whether the line, whose first 16 bytes' classes are `first`, has `shape` (and `fields`).
bool LineShapes::Matches(const Shape& shape, const char* line, __m128i first, int fields) {
  if (shape.fields != fields) return false;
  const auto same_bits = [&](const __m128i classes, int vector) {
    const __m128i known =
        _mm_loadu_si128(reinterpret_cast<const __m128i*>(shape.classes.data() + 16 * vector));
    return static_cast<std::uint64_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(classes, known)))
           << (16 * vector);
  };
  std::uint64_t same = same_bits(first, 0);
  for (int v = 1; v < shape.vectors; ++v) {
    std::uint32_t unused = 0;
    same |= same_bits(ClassesOf(line + 16 * v, &unused), v);
  }
  return (same & shape.checked) == shape.checked;
}

const char* LineShapes::Read(const char* line, int fields, double* values) const {
  std::uint32_t digit_bits = 0;
  const __m128i first = ClassesOf(line, &digit_bits);
  const int set = SetOf(digit_bits);
  const Shape* shape = &shapes_[static_cast<size_t>(kWays * set)];
  if (!Matches(*shape, line, first, fields)) {
    ++shape;
    if (!Matches(*shape, line, first, fields)) return nullptr;
  }
  if (fields == kMaxFields)
    ValuesAt<kMaxFields>(line, *shape, values);
  else
    for (int f = 0; f < fields; ++f)
      values[f] = ValueAt(line, shape->numbers[static_cast<size_t>(f)]);
  return line + shape->lf_at;
}

void LineShapes::Learn(const char* line, const char* eol, int fields) {
  const long lf_at = eol - line;
  if (lf_at > kMaxLineBytes || fields > kMaxFields) return;
  Shape shape;
  shape.fields = fields;
  shape.lf_at = static_cast<int>(lf_at);
  shape.vectors = static_cast<int>(lf_at / 16 + 1);
  shape.checked = (std::uint64_t{2} << lf_at) - 1;
  // The classes Read compares, by the same function (bytes past the LF are never compared).
  std::uint32_t digit_bits = 0;
  for (int v = 0; v < shape.vectors; ++v) {
    std::uint32_t bits = 0;
    _mm_storeu_si128(reinterpret_cast<__m128i*>(shape.classes.data() + 16 * v),
                     ClassesOf(line + 16 * v, &bits));
    if (v == 0) digit_bits = bits;
  }
  // The numbers, in a line the padded parse accepted: separators, then [-]digits[.digits].
  long i = 0;
  for (int f = 0; f < fields; ++f) {
    while (line[i] == ' ' || line[i] == '\t' || line[i] == ',' || line[i] == ';') ++i;
    Number& n = shape.numbers[static_cast<size_t>(f)];
    n.sign = line[i] == '-' ? -1.0 : 1.0;
    if (line[i] == '-') ++i;
    n.digits_at = static_cast<std::int8_t>(i);
    while (IsDigit(line[i])) ++i;
    n.digits_shift = static_cast<std::int8_t>(8 * (8 - (i - n.digits_at)));
    if (line[i] == '.') {
      n.fraction_at = static_cast<std::int8_t>(++i);
      while (IsDigit(line[i])) ++i;
      n.fraction = static_cast<std::int8_t>(i - n.fraction_at);
      n.fraction_shift = static_cast<std::int8_t>(8 * (8 - n.fraction));
    }
  }
  // Into the set's way learned the longer ago (the ways take turns).
  const int set = SetOf(digit_bits);
  const int way = next_way_[static_cast<size_t>(set)];
  next_way_[static_cast<size_t>(set)] = static_cast<std::uint8_t>((way + 1) % kWays);
  shapes_[static_cast<size_t>(kWays * set + way)] = shape;
}

#else  // no SSE2: every line the long way

const char* LineShapes::Read(const char*, int, double*) const { return nullptr; }
void LineShapes::Learn(const char*, const char*, int) {}

#endif

}  // namespace accelcal::detail
