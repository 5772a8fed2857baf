// The learned shapes of plain lines (issue 18): a line is read by a learned shape only when it
// has that shape, character for character but for its digits, and then with the values the
// number-by-number scan gives (decimal_scan.h's ScanShortDecimal), bit for bit.
#include "accelcal/base/line_shapes.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include "test_support.h"

namespace accelcal::detail {
namespace {

// A line in a buffer with room for Read's reach after it.
std::string Padded(const std::string& line) {
  std::string text = line;
  text.resize(line.size() + LineShapes::kReach + 8, '9');
  return text;
}

void LearnLine(LineShapes* shapes, const std::string& line, int fields) {
  const std::string text = Padded(line);
  shapes->Learn(text.data(), text.data() + line.find('\n'), fields);
}

// The numbers of a line by from_chars, token by token (blanks, commas, semicolons between).
std::vector<double> Reference(const std::string& line) {
  std::vector<double> values;
  size_t i = 0;
  while (i < line.size() && line[i] != '\r' && line[i] != '\n') {
    if (line[i] == ' ' || line[i] == '\t' || line[i] == ',' || line[i] == ';') {
      ++i;
      continue;
    }
    double v = 0.0;
    const auto [next, ec] = std::from_chars(line.data() + i, line.data() + line.size(), v);
    EXPECT_TRUE(ec == std::errc()) << line;
    values.push_back(v);
    i = static_cast<size_t>(next - line.data());
  }
  return values;
}

using accelcal::testing::SameBits;

// Reads `line` by the shapes; nullopt-like: returns false when no shape is its own.
bool ReadLine(const LineShapes& shapes, const std::string& line, int fields,
              std::vector<double>* values) {
  const std::string text = Padded(line);
  values->assign(static_cast<size_t>(fields), 0.0);
  const char* lf = shapes.Read(text.data(), fields, values->data());
  if (lf == nullptr) return false;
  EXPECT_EQ(lf, text.data() + line.find('\n')) << line;
  return true;
}

#if defined(__SSE2__)

TEST(LineShapes, ReadsALineOfALearnedShapeAsFromChars) {
  LineShapes shapes;
  LearnLine(&shapes, "1999.997 2057 -2047 2406 25\n", 5);
  std::vector<double> values;
  const std::string line = "2000.123 1111 -2222 3333 44\n";
  ASSERT_TRUE(ReadLine(shapes, line, 5, &values));
  const std::vector<double> ref = Reference(line);
  for (size_t f = 0; f < 5; ++f) EXPECT_TRUE(SameBits(values[f], ref[f])) << f;
  // CR LF is part of the shape.
  LearnLine(&shapes, "1 2 3 4\r\n", 4);
  ASSERT_TRUE(ReadLine(shapes, "5 6 7 8\r\n", 4, &values));
  EXPECT_EQ(values, (std::vector<double>{5, 6, 7, 8}));
  // "-0" reads as -0, as the scan reads it.
  LearnLine(&shapes, "-1 2 3 4\n", 4);
  ASSERT_TRUE(ReadLine(shapes, "-0 2 3 4\n", 4, &values));
  EXPECT_TRUE(std::signbit(values[0]));
}

TEST(LineShapes, ALineOfAnotherShapeIsNotRead) {
  LineShapes shapes;
  LearnLine(&shapes, "12 34 56 78\n", 4);
  std::vector<double> values;
  EXPECT_TRUE(ReadLine(shapes, "98 76 54 32\n", 4, &values));
  for (const char* other : {"12,34 56 78\n", "12;34 56 78\n", "12\t34 56 78\n", "12 34 56 789\n",
                            "12 34 56 7\n", "-2 34 56 78\n", "12.4 56 78\n", "12 34 56 78\r\n",
                            "12 34 56 78 \n", "12 34 56 7x\n", "12 34 56 78 9\n",
                            " 2 34 56 78\n"}) {
    EXPECT_FALSE(ReadLine(shapes, other, 4, &values)) << other;
  }
  // The same shape with another field count is not its own either.
  EXPECT_FALSE(ReadLine(shapes, "98 76 54 32\n", 5, &values));
}

TEST(LineShapes, OnlyLinesThatFitTheCheckAreLearned) {
  LineShapes shapes;
  std::vector<double> values;
  // LF at kMaxLineBytes: learned; one byte more: not (blanks between the numbers make them).
  const auto line_with_lf_at = [](size_t lf_at) {
    return "1.5" + std::string(lf_at - 10, ' ') + "2 3 4 5\n";
  };
  const std::string longest = line_with_lf_at(LineShapes::kMaxLineBytes);
  ASSERT_EQ(longest.find('\n'), static_cast<size_t>(LineShapes::kMaxLineBytes));
  LearnLine(&shapes, longest, 5);
  EXPECT_TRUE(ReadLine(shapes, longest, 5, &values));
  const std::string too_long = line_with_lf_at(LineShapes::kMaxLineBytes + 1);
  LearnLine(&shapes, too_long, 5);
  EXPECT_FALSE(ReadLine(shapes, too_long, 5, &values));
}

// A logger's stream: t printed shortest, counts whose sign and digits change. Every line the
// shapes read gets the reference values; the others are learned. Most are read.
TEST(LineShapes, AStreamOfLinesReadsAsFromCharsAndMostlyByShape) {
  LineShapes shapes;
  std::mt19937 rng(18);
  std::uniform_int_distribution<int> count(-3000, 3000);
  long read = 0;
  const int lines = 50000;
  for (int i = 0; i < lines; ++i) {
    char buffer[96];
    const int ax = 2000 + count(rng) / 100, ay = count(rng) / 1000, az = -1500 + count(rng) / 50;
    const int n = std::snprintf(buffer, sizeof buffer, "%g %d %d %d 24.5\n", i / 1000.0, ax, ay, az);
    const std::string line(buffer, static_cast<size_t>(n));
    std::vector<double> values;
    if (ReadLine(shapes, line, 5, &values)) {
      ++read;
      const std::vector<double> ref = Reference(line);
      for (size_t f = 0; f < 5; ++f) ASSERT_TRUE(SameBits(values[f], ref[f])) << line;
    } else {
      LearnLine(&shapes, line, 5);
    }
  }
  EXPECT_GT(read, lines * 9 / 10);
}

#else

TEST(LineShapes, WithoutSse2NothingIsReadByShape) {
  LineShapes shapes;
  LearnLine(&shapes, "1 2 3 4\n", 4);
  std::vector<double> values;
  EXPECT_FALSE(ReadLine(shapes, "1 2 3 4\n", 4, &values));
}

#endif

}  // namespace
}  // namespace accelcal::detail
