#include "accelcal/base/safe_text.h"

#include <cstdint>

#include <fmt/core.h>

namespace accelcal {
namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD

bool IsContinuation(unsigned char c) { return (c & 0xC0) == 0x80; }

// The length of the well-formed UTF-8 sequence at text[at] (1..4) and its code point, or 0 when
// the byte there does not start one (RFC 3629, table 3-7 of the Unicode standard).
int SequenceAt(std::string_view text, size_t at, char32_t* code_point) {
  const auto byte = [&](size_t i) { return static_cast<unsigned char>(text[at + i]); };
  const unsigned char lead = byte(0);
  if (lead < 0x80) {
    *code_point = lead;
    return 1;
  }
  int length = 0;
  unsigned char second_lo = 0x80, second_hi = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) second_lo = 0xA0;  // no overlong forms
    if (lead == 0xED) second_hi = 0x9F;  // no surrogates
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) second_lo = 0x90;  // no overlong forms
    if (lead == 0xF4) second_hi = 0x8F;  // nothing above U+10FFFF
  } else {
    return 0;
  }
  if (at + static_cast<size_t>(length) > text.size()) return 0;
  if (byte(1) < second_lo || byte(1) > second_hi) return 0;
  for (int i = 2; i < length; ++i)
    if (!IsContinuation(byte(static_cast<size_t>(i)))) return 0;
  char32_t cp = lead & (0xFF >> (length + 1));
  for (int i = 1; i < length; ++i) cp = (cp << 6) | (byte(static_cast<size_t>(i)) & 0x3F);
  *code_point = cp;
  return length;
}

// Characters that must not reach a terminal or a one-line comment as they are.
bool NeedsEscape(char32_t cp) {
  return cp < 0x20 || cp == 0x7F || (cp >= 0x80 && cp <= 0x9F) || cp == 0x2028 || cp == 0x2029 ||
         cp == 0xFEFF || cp == 0xFFFE || cp == 0xFFFF;
}

void AppendHexBytes(std::string_view bytes, std::string* out) {
  for (char c : bytes) *out += fmt::format("\\x{:02X}", static_cast<unsigned char>(c));
}

}  // namespace

bool IsValidUtf8(std::string_view text) {
  char32_t cp = 0;
  for (size_t at = 0; at < text.size();) {
    const int n = SequenceAt(text, at, &cp);
    if (n == 0) return false;
    at += static_cast<size_t>(n);
  }
  return true;
}

std::string ToValidUtf8(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  char32_t cp = 0;
  for (size_t at = 0; at < text.size();) {
    const int n = SequenceAt(text, at, &cp);
    if (n == 0) {
      out += kReplacement;
      ++at;
    } else {
      out.append(text.substr(at, static_cast<size_t>(n)));
      at += static_cast<size_t>(n);
    }
  }
  return out;
}

std::string DisplayText(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  char32_t cp = 0;
  for (size_t at = 0; at < text.size();) {
    const int n = SequenceAt(text, at, &cp);
    if (n == 0) {
      AppendHexBytes(text.substr(at, 1), &out);
      ++at;
      continue;
    }
    const std::string_view sequence = text.substr(at, static_cast<size_t>(n));
    at += static_cast<size_t>(n);
    if (!NeedsEscape(cp)) {
      out.append(sequence);
    } else if (cp == '\n') {
      out += "\\n";
    } else if (cp == '\r') {
      out += "\\r";
    } else if (cp == '\t') {
      out += "\\t";
    } else {
      AppendHexBytes(sequence, &out);
    }
  }
  return out;
}

std::string ShortDisplayText(std::string_view text, size_t max_bytes) {
  std::string out = DisplayText(text);
  if (out.size() <= max_bytes || max_bytes == 0) return out;
  size_t cut = max_bytes - 1;  // room for "~"
  while (cut > 0 && IsContinuation(static_cast<unsigned char>(out[cut]))) --cut;
  return out.substr(0, cut) + "~";
}

std::string DisplayLines(std::string_view text) {
  std::string out;
  for (size_t start = 0;;) {
    const size_t end = text.find('\n', start);
    out += DisplayText(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return out;
    out += '\n';
    start = end + 1;
  }
}

}  // namespace accelcal
