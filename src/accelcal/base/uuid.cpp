#include "accelcal/base/uuid.h"

#include <array>
#include <cstdint>
#include <random>

#include <fmt/core.h>

namespace accelcal {

std::string NewRandomUuid() {
  std::random_device entropy;
  std::array<std::uint8_t, 16> b{};
  for (size_t i = 0; i < b.size(); i += 4) {
    const std::uint32_t word = entropy();
    for (size_t j = 0; j < 4; ++j) b[i + j] = static_cast<std::uint8_t>(word >> (8 * j));
  }
  b[6] = static_cast<std::uint8_t>((b[6] & 0x0F) | 0x40);  // version 4
  b[8] = static_cast<std::uint8_t>((b[8] & 0x3F) | 0x80);  // variant 10xx (RFC 9562)
  std::string text;
  for (size_t i = 0; i < b.size(); ++i) {
    if (i == 4 || i == 6 || i == 8 || i == 10) text += '-';
    text += fmt::format("{:02x}", b[i]);
  }
  return text;
}

bool IsUuidText(std::string_view text) {
  if (text.size() != 36) return false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const bool dash_place = i == 8 || i == 13 || i == 18 || i == 23;
    if (dash_place != (c == '-')) return false;
    if (!dash_place && !((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

}  // namespace accelcal
