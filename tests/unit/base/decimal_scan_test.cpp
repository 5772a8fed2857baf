// The fast decimal scan (issue 18) against std::from_chars, the reference: every token it takes
// gives the very same double (bit for bit, sign of zero included), and what it declines is left
// to from_chars (so errors stay worded as before).
#include "accelcal/base/decimal_scan.h"

#include <cctype>
#include <charconv>
#include <cstring>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include "test_support.h"

namespace accelcal::detail {
namespace {

using accelcal::testing::SameBits;

// Scans `token`; when taken, checks it against from_chars. Returns whether it was taken.
bool TakenAndExact(const std::string& token) {
  double fast = 0.0;
  const char* b = token.data();
  const char* e = b + token.size();
  if (!ScanSimpleDecimal(b, e, &fast)) return false;
  double ref = 0.0;
  const auto [next, ec] = std::from_chars(b, e, ref);
  EXPECT_TRUE(ec == std::errc() && next == e) << "taken but from_chars refuses '" << token << "'";
  EXPECT_TRUE(SameBits(fast, ref)) << token << ": " << fast << " vs " << ref;
  return true;
}

TEST(DecimalScan, TakesTheFormsOfSampleTablesExactly) {
  for (const char* t : {"0", "-0", "33096", "-12", "0.03987", "2.9840000e-02", "3.3108000e+04",
                        "1e22", "9007199254740992", "-0.0", "123.456E3", "1.5e-7", "24.5"})
    EXPECT_TRUE(TakenAndExact(t)) << t;
}

TEST(DecimalScan, LeavesEverythingElseToFromChars) {
  for (const char* t : {"", "-", ".5", "5.", "1e", "1e+", "+1", "--1", "1x", "0x1p3", "inf", "nan",
                        "1e23", "1e-23", "9007199254740993", "12345678901234567890", "1,5", "1e00001",
                        " 1", "1 "})
    EXPECT_FALSE(TakenAndExact(t)) << t;
}

TEST(DecimalScan, RandomTokensAgreeWithFromCharsBitForBit) {
  std::mt19937_64 rng(18);
  std::uniform_int_distribution<int> len(1, 18), digit(0, 9), exp(-30, 30), coin(0, 3);
  int taken = 0;
  for (int i = 0; i < 200000; ++i) {
    std::string t;
    if (coin(rng) == 0) t += '-';
    const int n = len(rng);
    const int point = coin(rng) == 0 ? -1 : std::uniform_int_distribution<int>(1, n)(rng);
    for (int k = 0; k < n; ++k) {
      if (k == point) t += '.';
      t += static_cast<char>('0' + digit(rng));
    }
    if (point == n) t += "0";
    if (coin(rng) == 0) t += (coin(rng) < 2 ? "e" : "E") + std::to_string(exp(rng));
    taken += TakenAndExact(t);
  }
  EXPECT_GT(taken, 100000);  // the common forms do take the fast path
}

// The digits are read eight at a time while eight bytes remain (decimal_scan.h): whatever byte
// ends a run, at whatever place in the eight, the number ends there with the same value.
TEST(DecimalScan, PrefixEndsAtTheFirstByteThatCannotContinueItInEveryLane) {
  for (int stop = 1; stop <= 15; ++stop) {  // 15 digits: below 2^53, so never declined
    for (int c = 0; c < 256; ++c) {
      if ((c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E') continue;
      std::string text;
      for (int k = 0; k < stop; ++k) text += static_cast<char>('1' + (k * 7) % 9);
      const std::string token = text;
      text += static_cast<char>(c);
      text += "9876543210987654";
      double value = 0.0;
      const char* end = ScanDecimalPrefix(text.data(), text.data() + text.size(), &value);
      ASSERT_EQ(end, text.data() + stop) << "stop " << stop << ", byte " << c;
      double ref = 0.0;
      std::from_chars(token.data(), token.data() + token.size(), ref);
      ASSERT_TRUE(SameBits(value, ref)) << token;
    }
  }
}

TEST(DecimalScan, PrefixOfTokensInsideALineAgreesWithFromChars) {
  std::mt19937_64 rng(1818);
  std::uniform_int_distribution<int> len(1, 18), digit(0, 9), coin(0, 3);
  for (int i = 0; i < 100000; ++i) {
    std::string token;
    if (coin(rng) == 0) token += '-';
    const int n = len(rng);
    const int point = coin(rng) == 0 ? -1 : std::uniform_int_distribution<int>(1, n - 1 > 0 ? n - 1 : 1)(rng);
    for (int k = 0; k < n; ++k) {
      if (k == point && point < n) token += '.';
      token += static_cast<char>('0' + digit(rng));
    }
    const std::string line = token + (coin(rng) < 2 ? " " : ",") + "33096 33336 36437";
    double value = 0.0;
    const char* end = ScanDecimalPrefix(line.data(), line.data() + line.size(), &value);
    double ref = 0.0;
    const auto [next, ec] = std::from_chars(token.data(), token.data() + token.size(), ref);
    if (end == nullptr) continue;  // declined: from_chars reads it
    ASSERT_EQ(end, line.data() + token.size()) << line;
    ASSERT_TRUE(ec == std::errc() && next == token.data() + token.size()) << token;
    ASSERT_TRUE(SameBits(value, ref)) << token;
  }
}

// The short form, read without bounds from a padded buffer (decimal_scan.h): what it takes is
// from_chars's double for the same characters, ending where the digits end; it takes exactly the
// tokens [-]D{1,7}[.D{1,7}], whatever follows them.
TEST(DecimalScan, ShortFormAgreesWithFromCharsAndTakesExactlyItsForm) {
  std::mt19937_64 rng(1819);
  std::uniform_int_distribution<int> len(0, 9), digit(0, 9), coin(0, 3), follow(0, 6);
  const char* followers[] = {" 12", ",", "\n", "e5", ".5", "x", ""};
  int taken = 0;
  for (int i = 0; i < 200000; ++i) {
    std::string token;
    const bool negative = coin(rng) == 0;
    if (negative) token += '-';
    const int int_digits = len(rng);
    for (int k = 0; k < int_digits; ++k) token += static_cast<char>('0' + digit(rng));
    const bool point = coin(rng) != 0;
    const int frac_digits = point ? len(rng) : 0;
    if (point) token += '.';
    for (int k = 0; k < frac_digits; ++k) token += static_cast<char>('0' + digit(rng));
    std::string padded = token + followers[follow(rng)];
    padded.resize(token.size() + kShortDecimalReach + 8, '7');  // digits after: not a bound
    double value = 0.0;
    const char* end = ScanShortDecimal(padded.data(), &value);
    const bool short_form = int_digits >= 1 && int_digits <= 7 &&
                            (!point || (frac_digits >= 1 && frac_digits <= 7));
    // A follower that would continue the token (a digit, or a point after digits without one)
    // makes another token: skip it.
    const char after = padded[token.size()];
    if (std::isdigit(static_cast<unsigned char>(after)) || (!point && after == '.')) continue;
    ASSERT_EQ(end != nullptr, short_form) << "'" << token << "'";
    if (end == nullptr) continue;
    ++taken;
    ASSERT_EQ(end, padded.data() + token.size()) << token;
    double ref = 0.0;
    const auto [next, ec] = std::from_chars(token.data(), token.data() + token.size(), ref);
    ASSERT_TRUE(ec == std::errc() && next == token.data() + token.size()) << token;
    ASSERT_TRUE(SameBits(value, ref)) << token << ": " << value << " vs " << ref;
  }
  EXPECT_GT(taken, 50000);
}

}  // namespace
}  // namespace accelcal::detail
