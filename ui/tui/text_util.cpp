#include "tui/text_util.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/core.h>

namespace accelcal::ui {

namespace {

// UTF-8 sequences the engine is likely to use, with their ASCII stand-ins.
constexpr std::pair<std::string_view, std::string_view> kFolds[] = {
    {"\xE2\x80\x94", "--"},   // em dash (also the NaN mark of docs/STYLE.md)
    {"\xE2\x80\x93", "-"},    // en dash
    {"\xC2\xB0", " deg"},     // degree sign
    {"\xC2\xB1", "+-"},       // plus-minus
    {"\xC2\xB5", "u"},        // micro sign
    {"\xCF\x83", "sigma"},    // Greek small sigma
    {"\xE2\x80\xA6", "..."},  // ellipsis
};

size_t Utf8Length(unsigned char lead) {
  if (lead >= 0xF0) return 4;
  if (lead >= 0xE0) return 3;
  if (lead >= 0xC0) return 2;
  return 1;
}

}  // namespace

std::string Asciify(std::string_view text) {
  std::string out;
  size_t i = 0;
  while (i < text.size()) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      out += (c == '\t') ? ' ' : static_cast<char>(c);
      ++i;
      continue;
    }
    const size_t n = Utf8Length(c);
    const std::string_view seq = text.substr(i, n);
    std::string_view fold = "?";
    for (const auto& [from, to] : kFolds) {
      if (seq == from) fold = to;
    }
    out += fold;
    i += n;
  }
  return out;
}

std::vector<std::string> Wrap(std::string_view text, int width) {
  std::vector<std::string> lines;
  if (width <= 0) return lines;
  const size_t w = static_cast<size_t>(width);
  std::string current;
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && text[i] == ' ') ++i;
    size_t end = text.find(' ', i);
    if (end == std::string_view::npos) end = text.size();
    std::string_view word = text.substr(i, end - i);
    i = end;
    if (word.empty()) break;
    if (!current.empty() && current.size() + 1 + word.size() > w) {
      lines.push_back(current);
      current.clear();
    }
    while (word.size() > w) {  // a word longer than a line is cut
      if (!current.empty()) lines.push_back(current), current.clear();
      lines.emplace_back(word.substr(0, w));
      word.remove_prefix(w);
    }
    if (!current.empty()) current += ' ';
    current += word;
  }
  if (!current.empty()) lines.push_back(current);
  return lines;
}

std::string FormatNumber(double value, int decimals, int width) {
  if (std::isnan(value)) return fmt::format("{:>{}}", "--", width);
  return fmt::format("{:>{}.{}f}", value, width, decimals);
}

std::string Clip(std::string_view text, int width) {
  if (width <= 0) return {};
  return std::string(text.substr(0, static_cast<size_t>(width)));
}

std::vector<std::string> WrapLines(const std::vector<std::string>& lines, int width) {
  if (width <= 0) return lines;
  const size_t w = static_cast<size_t>(width);
  std::vector<std::string> out;
  for (const std::string& line : lines) {
    // Deeply indented lines on a narrow screen keep at least half the width for their words.
    const size_t lead = std::min(std::min(line.find_first_not_of(' '), line.size()), w / 2);
    std::string rest = line;
    // Broken at the last blank that fits, the blanks inside each piece kept (table columns stay
    // aligned within a row); a piece without a blank is cut.
    while (rest.size() > w) {
      const size_t from = lead + 3;  // past a continuation's indent: every piece holds a word
      size_t cut = rest.rfind(' ', w);
      if (cut == std::string::npos || cut < from) cut = w;
      std::string piece = rest.substr(0, cut);
      while (!piece.empty() && piece.back() == ' ') piece.pop_back();
      out.push_back(piece);
      const size_t next = std::min(rest.find_first_not_of(' ', cut), rest.size());
      rest = std::string(lead + 2, ' ') + rest.substr(next);
      if (rest.size() <= lead + 2) break;
    }
    if (rest.size() > lead + 2 || out.empty() || rest == line) out.push_back(rest);
  }
  return out;
}

}  // namespace accelcal::ui
