// Small text-scanning helpers shared by the file readers: lines, blanks, columns, numbers.
// Internal to src/ (nothing in ui/ includes detail/).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace accelcal::detail {

// `text` without a leading UTF-8 byte-order mark (EF BB BF), if it has one.
std::string_view StripBom(std::string_view text);

// Walks the lines of a text. Accepts "\n" and "\r\n" terminators; a last line without a
// terminator still counts. Does NOT take ownership: the text must outlive the reader.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : rest_(text) {}
  // The next line without its terminator; false at the end of the text.
  bool Next(std::string_view* line);
  // 1-based number of the line last returned by Next (0 before the first call).
  long line_number() const { return line_number_; }

 private:
  std::string_view rest_;
  bool done_ = false;
  long line_number_ = 0;
};

inline bool IsBlank(char c) { return c == ' ' || c == '\t'; }

// `text` without leading and trailing spaces and tabs.
std::string_view TrimBlanks(std::string_view text);

// The 1-based column of byte `offset` within `line`, counted in characters (UTF-8 code points),
// which is what editors show.
long ColumnAt(std::string_view line, size_t offset);

// Parses all of `text` as a decimal or scientific double. An optional leading '+' or '-' is
// accepted, and so are "nan" and "inf"/"infinity" in any case (non-finite results are the
// caller's to judge). False on anything else, including an empty text and trailing characters.
bool ParseDouble(std::string_view text, double* value);

// Parses all of `text` as a base-10 integer (optional sign); false otherwise or on overflow.
bool ParseLong(std::string_view text, long* value);

// `text` fit to quote in a message: bytes outside printable ASCII shown as '?', at most
// `max_chars` characters (then "...").
std::string PrintableExcerpt(std::string_view text, size_t max_chars);

// A number for messages: shortest form that reads back the same ("4095", "1.23", "1e-07").
std::string FormatNumber(double value);

}  // namespace accelcal::detail
