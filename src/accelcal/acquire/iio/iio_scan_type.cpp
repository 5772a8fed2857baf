#include "accelcal/acquire/iio/iio_scan_type.h"

#include <cctype>

#include <fmt/format.h>

namespace accelcal {
namespace {

// Reads a decimal number at text[*at...]; false when there is none.
bool ScanNumber(std::string_view text, size_t* at, int* value) {
  const size_t start = *at;
  long v = 0;
  while (*at < text.size() && std::isdigit(static_cast<unsigned char>(text[*at])) && *at - start < 4)
    v = 10 * v + (text[(*at)++] - '0');
  *value = static_cast<int>(v);
  return *at > start;
}

bool Expect(std::string_view text, size_t* at, std::string_view what) {
  if (text.substr(*at, what.size()) != what) return false;
  *at += what.size();
  return true;
}

}  // namespace

std::int64_t IioScanType::Decode(const std::uint8_t* bytes) const {
  const int n = StorageBytes();
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint8_t b = bytes[big_endian ? i : n - 1 - i];
    v = (v << 8) | b;
  }
  v >>= shift;
  if (bits < 64) v &= (std::uint64_t{1} << bits) - 1;
  if (is_signed && bits < 64 && (v & (std::uint64_t{1} << (bits - 1))) != 0)
    v |= ~((std::uint64_t{1} << bits) - 1);
  return static_cast<std::int64_t>(v);
}

std::string IioScanType::Describe() const {
  return repeat > 1 ? fmt::format("{}:{}{}/{}X{}>>{}", big_endian ? "be" : "le", is_signed ? 's' : 'u',
                                  bits, storage_bits, repeat, shift)
                    : fmt::format("{}:{}{}/{}>>{}", big_endian ? "be" : "le", is_signed ? 's' : 'u',
                                  bits, storage_bits, shift);
}

std::optional<IioScanType> ParseIioScanType(std::string_view text, std::string* why) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  const std::string shown(text);
  auto refuse = [&](const std::string& what) -> std::optional<IioScanType> {
    *why = fmt::format("scan type '{}' not understood: {} (expected e.g. le:s12/16>>4)", shown, what);
    return std::nullopt;
  };
  IioScanType t;
  size_t at = 0;
  if (Expect(text, &at, "le:")) t.big_endian = false;
  else if (Expect(text, &at, "be:")) t.big_endian = true;
  else return refuse("it does not start with le: or be:");
  if (at >= text.size()) return refuse("no sign letter");
  const char sign = text[at++];
  if (sign == 's' || sign == 'S') t.is_signed = true;
  else if (sign == 'u' || sign == 'U') t.is_signed = false;
  else return refuse(fmt::format("sign '{}' is neither s nor u", sign));
  if (!ScanNumber(text, &at, &t.bits) || !Expect(text, &at, "/") || !ScanNumber(text, &at, &t.storage_bits))
    return refuse("no BITS/STORAGEBITS");
  if (Expect(text, &at, "X") && !ScanNumber(text, &at, &t.repeat)) return refuse("no repeat count after X");
  if (!Expect(text, &at, ">>") || !ScanNumber(text, &at, &t.shift)) return refuse("no >>SHIFT");
  if (at != text.size()) return refuse(fmt::format("'{}' left over", text.substr(at)));
  if (t.storage_bits != 8 && t.storage_bits != 16 && t.storage_bits != 32 && t.storage_bits != 64)
    return refuse(fmt::format("storage of {} bits (8, 16, 32 or 64 expected)", t.storage_bits));
  if (t.bits < 1 || t.bits + t.shift > t.storage_bits)
    return refuse(fmt::format("{} bits shifted by {} do not fit {} bits of storage", t.bits, t.shift, t.storage_bits));
  if (t.repeat < 1) return refuse("a repeat of 0");
  return t;
}

}  // namespace accelcal
