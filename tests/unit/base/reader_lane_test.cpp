// The sample reader's lane of plain lines (issue 18: long files read straight from the buffer,
// most lines by their learned shape) against the same reader fed a few bytes at a time, where
// the lane never opens (it needs SampleLineParser::kPaddedLineReach bytes ahead). Whatever the
// file, both must give the same samples bit for bit, the same summary, and the same error (line,
// column, message) or, skipping malformed lines, the same count and the same last complaint.
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/base/sample_reader.h"
#include "test_support.h"

namespace accelcal {
namespace {

struct Reading {
  std::vector<Sample> samples;
  std::string summary;
  std::string error;  // "line:column: message" of the error thrown, if any
  long malformed = 0;
  std::string last_malformed;
  long line_number = 0;  // lines seen
};

// Reads `text` whole (one Consume: the lane opens) or in pieces of at most `piece` bytes.
Reading Read(const std::string& text, SampleReader::OnMalformed policy, size_t piece,
             const SampleFormat& format = {}) {
  SampleReader reader("rec.txt", format, policy);
  Reading r;
  try {
    if (piece == 0) {
      // In a buffer of exactly the text's size: a read past it shows in the sanitizer build.
      const std::vector<char> exact(text.begin(), text.end());
      reader.Consume(std::string_view(exact.data(), exact.size()), true, &r.samples);
    } else {
      std::mt19937 rng(static_cast<unsigned>(text.size()));
      std::uniform_int_distribution<size_t> size(1, piece);
      for (size_t at = 0; at < text.size();) {
        const size_t n = std::min(size(rng), text.size() - at);
        reader.Feed(std::string_view(text).substr(at, n), &r.samples);
        at += n;
      }
    }
    reader.Finish(&r.samples);
    const ReadingSummary summary = reader.Summary();
    r.summary = fmt::format("{} ({} data rows, {} skipped)", summary.Describe(), summary.data_rows,
                            summary.skipped_rows);
  } catch (const InputError& e) {
    r.error = fmt::format("{}:{}: {}", e.line(), e.column(), e.message());
  }
  r.malformed = reader.malformed();
  r.line_number = reader.line_number();
  r.last_malformed = reader.last_malformed();
  return r;
}

using accelcal::testing::SameBits;

void ExpectSameReading(const std::string& text, SampleReader::OnMalformed policy,
                       const SampleFormat& format = {}) {
  const Reading whole = Read(text, policy, 0, format);
  const Reading fed = Read(text, policy, 64, format);
  ASSERT_EQ(whole.error, fed.error);
  ASSERT_EQ(whole.summary, fed.summary);
  ASSERT_EQ(whole.malformed, fed.malformed);
  ASSERT_EQ(whole.last_malformed, fed.last_malformed);
  ASSERT_EQ(whole.line_number, fed.line_number);
  ASSERT_EQ(whole.samples.size(), fed.samples.size());
  for (size_t i = 0; i < whole.samples.size(); ++i) {
    const Sample& a = whole.samples[i];
    const Sample& b = fed.samples[i];
    ASSERT_TRUE(SameBits(a.t_s, b.t_s) && SameBits(a.temp_c, b.temp_c) &&
                SameBits(a.raw_counts(0), b.raw_counts(0)) &&
                SameBits(a.raw_counts(1), b.raw_counts(1)) &&
                SameBits(a.raw_counts(2), b.raw_counts(2)))
        << "sample " << i;
  }
}

// A long recording as loggers write them: t printed shortest at 1 kHz ("0.99", "0.991",
// "1"), counts whose sign and number of digits change, a temperature with or without decimals;
// here and there a comment, a blank line, CR LF, commas, tabs, aligned columns, an exponent.
std::string LoggerText(int lines, unsigned seed, bool with_temp) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> count(-2500, 2500), rare(0, 99);
  std::string text = "# t ax ay az temp_c\n";
  for (int i = 0; i < lines; ++i) {
    const std::string t = fmt::format("{}", i / 1000.0);
    const int ax = count(rng), ay = 2048 + count(rng) / 100, az = count(rng) / 3;
    const std::string temp = with_temp ? (rare(rng) < 50 ? " 25" : " 24.75") : "";
    const int kind = rare(rng);
    if (kind == 0) text += "# a comment\n";
    if (kind == 1) text += "\n";
    if (kind == 2) {
      const std::string comma_temp = temp.empty() ? "" : "," + temp.substr(1);
      text += fmt::format("{},{},{},{}{}\r\n", t, ax, ay, az, comma_temp);
    } else if (kind == 3) {
      text += fmt::format("{}\t{}\t{}\t{}{}\n", t, ax, ay, az, temp);
    } else if (kind == 4) {
      text += fmt::format("{:>10} {:>6} {:>6} {:>6}{}\n", t, ax, ay, az, temp);
    } else if (kind == 5) {
      text += fmt::format("{}, {}, {}, {}{}\n", t, ax, ay, az, temp.empty() ? "" : "," + temp);
    } else if (kind == 6) {
      text += fmt::format("{} {}e0 {} {}{}\n", t, ax, ay, az, temp);
    } else {
      text += fmt::format("{} {} {} {}{}\n", t, ax, ay, az, temp);
    }
  }
  return text;
}

TEST(ReaderLane, LongRecordingsReadAsLineByLine) {
  for (const bool with_temp : {true, false}) {
    const std::string text = LoggerText(6000, with_temp ? 1u : 2u, with_temp);
    ExpectSameReading(text, SampleReader::OnMalformed::kThrow);
    ExpectSameReading(text, SampleReader::OnMalformed::kSkip);
    // The counts as g: the reading scale applies on the lane too.
    SampleFormat in_g;
    in_g.unit = *StringToReadingUnit("g");
    in_g.unit_declared = true;
    ExpectSameReading(text, SampleReader::OnMalformed::kThrow, in_g);
  }
  // Other settings of the reading: skipped rows, t from the rate (the lane stays closed), a
  // temperature required, ties refused, a line limit under the lane's reach.
  const std::string text = LoggerText(3000, 5u, true);
  SampleFormat skip;
  skip.skip_rows = 1500;
  SampleFormat rate;
  rate.rate_hz = 1000.0;
  SampleFormat temp;
  temp.require_temp_c = "this reading needs temp_c on every line";
  SampleFormat no_repair;
  no_repair.repair_ties = false;
  SampleFormat short_lines;
  short_lines.max_line_bytes = 100;
  for (const SampleFormat& format : {skip, rate, temp, no_repair, short_lines}) {
    ExpectSameReading(text, SampleReader::OnMalformed::kThrow, format);
    ExpectSameReading(text, SampleReader::OnMalformed::kSkip, format);
    if (HasFatalFailure()) return;
  }
  ExpectSameReading(LoggerText(3000, 6u, false), SampleReader::OnMalformed::kSkip, temp);
  // Sanity: the lane had lines to read (the whole reading has them all).
  const Reading whole = Read(LoggerText(6000, 1u, true), SampleReader::OnMalformed::kThrow, 0);
  EXPECT_EQ(whole.error, "");
  EXPECT_EQ(whole.samples.size(), 6000u);
}

// A broken line deep in a long file (where the lane reads): the same error, at the same line
// and column, and, skipping, the same samples around it.
TEST(ReaderLane, BrokenLinesDeepInALongFileGiveTheSameError) {
  const std::string good = LoggerText(4000, 3u, true);
  const size_t at = good.find('\n', good.size() / 2) + 1;  // the start of a line past 1000 rows
  for (const char* bad : {"1.5 20x2 3 4 5\n", "0.0005 1 2 3 4\n", "1 2 3 4 5 6\n", "1 2 3\n",
                          "2.0001 1e999 2 3 4\n", "2.0001 1 2 3 nan\n", "2.0001 -- 2 3 4\n",
                          "2.0001 1 2 3 4,\n", "2.0001 1,,2 3 4\n", "2.0001 1 2 3 4\r\r\n",
                          "2.00010000000 12345678 2 3 4\n", "2.0001 1 2 3 4 \n"}) {
    std::string text = good;
    text.insert(at, bad);
    ExpectSameReading(text, SampleReader::OnMalformed::kThrow);
    ExpectSameReading(text, SampleReader::OnMalformed::kSkip);
    if (HasFatalFailure()) return;
  }
  // A t that repeats the one before it (a tie) past the lane's start.
  std::string tie = good;
  const size_t next = tie.find('\n', at) + 1;
  tie.insert(next, tie.substr(at, next - at));
  ExpectSameReading(tie, SampleReader::OnMalformed::kThrow);
  ExpectSameReading(tie, SampleReader::OnMalformed::kSkip);
}

// Lines that share the places of their digits but not their other characters, or their
// length: a shape learned from one must not read the other.
TEST(ReaderLane, LinesAlikeButForTheirSeparatorsOrSignsReadAsTheirOwn) {
  std::string text;
  const char* forms[] = {"{} 12 34 56\n", "{},12 34 56\n", "{} 12,34 56\n", "{};12 34 56\n",
                         "{}\t12 34 56\n", "{} -2 34 56\n", "{} 12 34 567\n", "{} 12.3 4 56\n",
                         "{} 12 34 56\r\n", "{} 12 34 -6\n"};
  for (int i = 0; i < 5000; ++i) text += fmt::format(fmt::runtime(forms[(i * 7) % 10]), 100 + i);
  ExpectSameReading(text, SampleReader::OnMalformed::kThrow);
  const Reading whole = Read(text, SampleReader::OnMalformed::kThrow, 0);
  ASSERT_EQ(whole.samples.size(), 5000u);
  EXPECT_EQ(whole.samples[4999].raw_counts(2), 56.0);  // 4999 * 7 % 10 == 3: "{};12 34 56"
}

// Random edits of a long file: whatever they break, both readings agree.
TEST(ReaderLane, RandomEditsOfALongFileReadTheSameBothWays) {
  const std::string base = LoggerText(2500, 4u, true);
  std::mt19937 rng(18);
  std::uniform_int_distribution<size_t> where(0, base.size() - 1);
  std::uniform_int_distribution<int> edits(1, 6);
  const std::string alphabet = "0123456789 .-,;\t\r\nex#+";
  std::uniform_int_distribution<size_t> pick(0, alphabet.size() - 1);
  for (int mutant = 0; mutant < 150; ++mutant) {
    std::string text = base;
    for (int k = edits(rng); k > 0; --k) {
      const size_t at = where(rng) % text.size();
      if (k % 2 == 0)
        text[at] = alphabet[pick(rng)];
      else
        text.insert(at, 1, alphabet[pick(rng)]);
    }
    ExpectSameReading(text, mutant % 2 == 0 ? SampleReader::OnMalformed::kThrow
                                            : SampleReader::OnMalformed::kSkip);
    if (HasFatalFailure()) {
      ADD_FAILURE() << "mutant " << mutant;
      return;
    }
  }
}

}  // namespace
}  // namespace accelcal
