#include "accelcal/base/text_scan.h"

#include <algorithm>
#include <charconv>
#include <cstring>

#include <fmt/format.h>

namespace accelcal::detail {

std::string_view StripBom(std::string_view text) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  if (text.substr(0, kBom.size()) == kBom) text.remove_prefix(kBom.size());
  return text;
}

bool LineReader::Next(std::string_view* line) {
  if (done_ || rest_.empty()) {
    done_ = true;
    return false;
  }
  const size_t eol = rest_.find('\n');
  std::string_view current = rest_.substr(0, eol);
  if (eol == std::string_view::npos) {
    done_ = true;
    rest_ = {};
  } else {
    rest_.remove_prefix(eol + 1);
  }
  if (!current.empty() && current.back() == '\r') current.remove_suffix(1);
  ++line_number_;
  *line = current;
  return true;
}

std::string_view TrimBlanks(std::string_view text) {
  while (!text.empty() && IsBlank(text.front())) text.remove_prefix(1);
  while (!text.empty() && IsBlank(text.back())) text.remove_suffix(1);
  return text;
}

long ColumnAt(std::string_view line, size_t offset) {
  long column = 1;
  for (size_t i = 0; i < offset && i < line.size(); ++i) {
    // Continuation bytes (10xxxxxx) belong to the character before them.
    if ((static_cast<unsigned char>(line[i]) & 0xC0) != 0x80) ++column;
  }
  if (offset > line.size()) column += static_cast<long>(offset - line.size());
  return column;
}

namespace {

// All of `text` as a number of type T. std::from_chars takes '-' but not '+'; a second sign
// after '+' is still refused.
template <typename T>
bool ParseWhole(std::string_view text, T* value) {
  const char* first = text.data();
  const char* last = first + text.size();
  if (first != last && *first == '+') {
    ++first;
    if (first != last && (*first == '+' || *first == '-')) return false;
  }
  if (first == last) return false;
  const auto [end, ec] = std::from_chars(first, last, *value);
  return ec == std::errc() && end == last;
}

}  // namespace

bool ParseDouble(std::string_view text, double* value) { return ParseWhole(text, value); }

bool ParseLong(std::string_view text, long* value) { return ParseWhole(text, value); }

std::string PrintableExcerpt(std::string_view text, size_t max_chars) {
  std::string out;
  out.reserve(std::min(text.size(), max_chars) + 3);
  for (char c : text) {
    if (out.size() >= max_chars) {
      out += "...";
      break;
    }
    const auto u = static_cast<unsigned char>(c);
    out += (u >= 0x20 && u < 0x7f) ? c : '?';
  }
  return out;
}

std::string FormatNumber(double value) { return fmt::format("{}", value); }

}  // namespace accelcal::detail
