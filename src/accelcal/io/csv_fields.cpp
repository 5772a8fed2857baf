#include "accelcal/io/csv_fields.h"

#include <algorithm>

#include "accelcal/base/text_scan.h"

namespace accelcal {

using detail::IsBlank;
using detail::TrimBlanks;
namespace {

size_t SkipBlanks(std::string_view line, size_t pos) {
  while (pos < line.size() && IsBlank(line[pos])) ++pos;
  return pos;
}

// Reads the quoted field whose opening quote is at `pos`; returns the offset just past the
// closing quote, or npos when the quote is not closed on this line.
size_t ReadQuoted(std::string_view line, size_t pos, std::string* value) {
  for (size_t i = pos + 1; i < line.size(); ++i) {
    if (line[i] != '"') {
      value->push_back(line[i]);
    } else if (i + 1 < line.size() && line[i + 1] == '"') {
      value->push_back('"');
      ++i;
    } else {
      return i + 1;
    }
  }
  return std::string_view::npos;
}

}  // namespace

CsvSplitError SplitCsvLine(std::string_view line, std::vector<CsvField>* fields) {
  fields->clear();
  size_t pos = 0;
  for (;;) {
    CsvField& field = fields->emplace_back();
    pos = SkipBlanks(line, pos);
    field.offset = pos;
    if (pos < line.size() && line[pos] == '"') {
      field.quoted = true;
      const size_t closed = ReadQuoted(line, pos, &field.value);
      if (closed == std::string_view::npos) return {"unterminated quote", pos};
      pos = SkipBlanks(line, closed);
      if (pos < line.size() && line[pos] != ',') {
        return {"unexpected character after a closing quote (expected ',' or end of line)", pos};
      }
    } else {
      const size_t comma = std::min(line.find(',', pos), line.size());
      field.value = std::string(TrimBlanks(line.substr(pos, comma - pos)));
      pos = comma;
    }
    if (pos >= line.size()) return {};
    ++pos;  // past the comma
  }
}

std::string CsvQuote(std::string_view field) {
  if (field.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(field);
  std::string quoted = "\"";
  for (char ch : field) {
    if (ch == '"') quoted += '"';
    quoted += ch;
  }
  return quoted + '"';
}

}  // namespace accelcal
