#include "tui/text_util.h"

#include <cmath>
#include <utility>

#include <fmt/core.h>

namespace accelcal::ui {

namespace {

// UTF-8 sequences the engine is likely to use, with their ASCII stand-ins.
constexpr std::pair<std::string_view, std::string_view> kFolds[] = {
    {"\xE2\x80\x94", "--"},   // em dash (also the NaN mark of STYLE.md)
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

}  // namespace accelcal::ui
