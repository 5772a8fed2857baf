// CSV fields (RFC 4180): splitting one line of a comma-separated file into fields (quoted fields
// within one line), and quoting one field for writing.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace accelcal {

struct CsvField {
  // The value: blanks around an unquoted value are trimmed; a quoted value keeps everything
  // between its quotes, with each doubled quote ("") read as one quote.
  std::string value;
  // Byte offset in the line of the field's first non-blank character (its opening quote when
  // quoted; the position just after the separator when the field is empty).
  size_t offset = 0;
  bool quoted = false;
};

// Why SplitCsvLine failed and where (byte offset in the line).
struct CsvSplitError {
  std::string message;  // empty on success
  size_t offset = 0;
};

// Splits `line` at commas outside quotes into `*fields` (cleared first). A field is quoted
// when its first non-blank character is '"'; only blanks may follow its closing quote. A quote
// inside an unquoted field is kept literally. Quoted fields cannot span lines: an opening quote
// without a closing one on the same line is an "unterminated quote".
CsvSplitError SplitCsvLine(std::string_view line, std::vector<CsvField>* fields);

// One CSV field for writing, quoted as RFC 4180 requires and only when needed: when it holds a
// comma, a quote, CR or LF (quotes doubled inside).
std::string CsvQuote(std::string_view field);

}  // namespace accelcal
