// The shapes of a long file's plain lines, learned and then used to read its next lines by
// position. A logger writes line after line of the same shape: "1999.997 2057 2047 2406 25"
// then "1999.998 2058 2045 2406 25", the same characters in the same places but for the
// digits. A line read the long way (SampleLineParser's padded parse, which checks it) teaches
// its shape: the line with every digit replaced by '0', and where each number's digits are. A
// later line is then checked against a learned shape with a few 16-byte compares (its digits
// where the digits were, every other character the same, its end in the same place) and its
// numbers read straight from their places: no character waits on the one before it, which is
// what bounds the long way's speed. The values are the long way's, bit for bit (the same digits
// through the same arithmetic, decimal_scan.h). Lines whose shape is not known go the long way.
//
// A few shapes are kept (a t column's last digits come and go: "0.99", "0.991", "1"); a new
// one takes the place of the one learned the longer ago in its set.
// Without SSE2 (not an x86-64 build) nothing is learned and every line goes the long way.
// Internal to src/.
#pragma once

#include <array>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace accelcal::detail {

class LineShapes {
 public:
  static constexpr int kMaxFields = 5;
  // A shape is learned from lines whose LF is at most this many bytes in.
  static constexpr int kMaxLineBytes = 62;
  // Read() and Learn() load up to 64 bytes from a line, and Read() 8 bytes from each number's
  // digits: the caller's buffer must hold kReach bytes past the line's start.
  static constexpr long kReach = 72;

  // Shapes are kept in kSets sets of kWays (a set chosen by the digits' places in the first 16
  // bytes): the shapes of one stretch of a file (a t column's "9.99", "9.991", "10") rarely
  // need more than two places in one set.
  static constexpr int kSets = 16;
  static constexpr int kWays = 2;

  // When the line at `line` has a learned shape of `fields` numbers: its numbers into
  // values[0 .. fields), and its LF. nullptr otherwise (values untouched).
  const char* Read(const char* line, int fields, double* values) const;
  // Learns the shape of the line at `line`, whose LF is at `eol`: the padded parse accepted
  // it, so it holds `fields` numbers in the short form, separated by blanks, commas or
  // semicolons. Lines too long to be checked at once are not learned.
  void Learn(const char* line, const char* eol, int fields);

 private:
  // Where a number's digits are, with what reading them takes (decimal_scan.h's arithmetic).
  struct Number {
    std::int8_t digits_at = 0;     // the first digit before the point
    std::int8_t digits_shift = 0;  // 8 * (8 - digits): ShiftedDigitsValue's shift
    std::int8_t fraction_at = 0;   // the first digit after it
    std::int8_t fraction = 0;      // digits after it: 0 (no point) to 7
    std::int8_t fraction_shift = 0;
    double sign = 1.0;             // -1 for a minus sign (x * -1 is exactly -x, and -0 for 0)
  };
  struct Shape {
    std::array<unsigned char, 64> classes{};  // the line, digits as '0', up to its LF
    std::uint64_t checked = 0;                // bits of the bytes to compare: the line and LF
    int vectors = 0;                          // 16-byte compares that cover them
    int fields = 0;                           // 0: an empty slot
    int lf_at = 0;
    std::array<Number, kMaxFields> numbers{};
  };
#if defined(__SSE2__)
  static bool Matches(const Shape& shape, const char* line, __m128i first, int fields);
#endif

  std::array<Shape, kSets * kWays> shapes_{};       // set s in [kWays s, kWays (s + 1))
  std::array<std::uint8_t, kSets> next_way_{};       // the way the set's next shape takes
};

}  // namespace accelcal::detail
