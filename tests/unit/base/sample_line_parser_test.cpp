// The one-pass path of plain lines (issue 18) against the general path it short-cuts: on lines
// both valid and broken, the same sample bit for bit and the same t offset, or the same error
// with the same column.
#include "accelcal/base/sample_line_parser.h"

#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "test_support.h"

namespace accelcal::detail {
namespace {

struct Outcome {
  std::optional<Sample> sample;
  size_t t_offset = 0;
  std::string error;  // "line:column: message" when refused
};

Outcome ParseWith(bool fast, const std::string& first_line, const std::string& line) {
  SampleLineParser parser("rec.txt");
  parser.SetPlainFastPath(fast);
  Sample ignored;
  parser.Parse(first_line, 1, &ignored);  // sets the field count, as the first data line does
  Outcome out;
  try {
    Sample s;
    out.t_offset = parser.Parse(line, 2, &s);
    out.sample = s;
  } catch (const InputError& e) {
    out.error = std::to_string(e.line()) + ":" + std::to_string(e.column()) + ": " + e.message();
  }
  return out;
}

using accelcal::testing::SameBits;

void ExpectSame(const std::string& first_line, const std::string& line) {
  const Outcome fast = ParseWith(true, first_line, line);
  const Outcome general = ParseWith(false, first_line, line);
  ASSERT_EQ(fast.error, general.error) << "'" << line << "'";
  ASSERT_EQ(fast.sample.has_value(), general.sample.has_value()) << line;
  if (!fast.sample) return;
  EXPECT_EQ(fast.t_offset, general.t_offset) << line;
  EXPECT_TRUE(SameBits(fast.sample->t_s, general.sample->t_s)) << line;
  for (int a = 0; a < 3; ++a)
    EXPECT_TRUE(SameBits(fast.sample->raw_counts(a), general.sample->raw_counts(a))) << line;
  EXPECT_TRUE(SameBits(fast.sample->temp_c, general.sample->temp_c)) << line;
}

TEST(SampleLineParser, PlainLinesReadTheSameByBothPaths) {
  for (const char* line : {"0.001 2054 2040 2400 25", "  2.9840000e-02   3.3108000e+04   3.3329000e+04   3.6429000e+04 24.5",
                           "1,2,3,4,5", "1 , 2 ,3, 4 ,5", "1\t2\t3\t4\t5", "-0 -1 -2.5 -3e2 -0.0",
                           "12345678901234567 1 2 3 4", "1 2 3 4 5   "})
    ExpectSame("0 1 2 3 4", line);
}

TEST(SampleLineParser, BrokenLinesGetTheSameErrorByBothPaths) {
  for (const char* line : {"1 2 3 4", "1 2 3 4 5 6", "1 2 x 4 5", "1 2 3 4 5,", "1,,2 3 4 5",
                           "+1 2 3 4 5", "1 2 3 4 nan", "1 2 3 4 1e999", "1.e3 2 3 4 5", "1 2 3 4 .5",
                           "1 2 3 4 5\r", "1 2;3 4 5", "1 2 3 4 5;", "1 2 3 4 0x10", "1-2 3 4 5 6"})
    ExpectSame("0 1 2 3 4", line);
}

// Random lines from the characters of numbers and separators, and a few others: whatever the
// one-pass path takes, it takes as the general path does, and what it declines the general path
// words.
TEST(SampleLineParser, RandomLinesAgreeByBothPaths) {
  const std::string alphabet = "0123456789012345678901234567890123456789..--+eE    ,,;\tx";
  std::mt19937_64 rng(1818);
  std::uniform_int_distribution<size_t> length(0, 40), pick(0, alphabet.size() - 1);
  std::uniform_int_distribution<int> coin(0, 2);
  for (int i = 0; i < 20000; ++i) {
    std::string line;
    if (coin(rng) == 0) {
      // A plausible line with one random edit, so that many lines are valid or nearly so.
      line = "0.00" + std::to_string(i % 10) + " 2054 -2040 " + std::to_string(i) + " 25.5";
      line[static_cast<size_t>(i) % line.size()] = alphabet[pick(rng)];
    } else {
      for (size_t k = length(rng); k > 0; --k) line += alphabet[pick(rng)];
    }
    if (line.find_first_not_of(" \t") == std::string::npos) continue;  // the reader skips blank lines
    ExpectSame(coin(rng) == 0 ? "0 1 2 3" : "0 1 2 3 4", line);
    if (HasFatalFailure()) return;
  }
}

}  // namespace
}  // namespace accelcal::detail
