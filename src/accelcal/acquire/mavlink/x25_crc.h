// The CRC of MAVLink frames: CRC-16/MCRF4XX, which the MAVLink documentation calls X.25 (poly
// 0x1021 reflected, initial 0xFFFF, no final xor), computed byte by byte as the reference
// implementation's crc_accumulate does (the algorithm as published in the MAVLink serialization
// documentation, "Checksum").
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace accelcal::mavlink {

class X25Crc {
 public:
  void Add(std::uint8_t byte) {
    std::uint8_t tmp = byte ^ static_cast<std::uint8_t>(crc_ & 0xFF);
    tmp ^= static_cast<std::uint8_t>(tmp << 4);
    crc_ = static_cast<std::uint16_t>((crc_ >> 8) ^ (tmp << 8) ^ (tmp << 3) ^ (tmp >> 4));
  }
  void Add(const std::uint8_t* bytes, size_t count) {
    for (size_t i = 0; i < count; ++i) Add(bytes[i]);
  }
  void Add(std::string_view text) {
    for (char c : text) Add(static_cast<std::uint8_t>(c));
  }
  std::uint16_t value() const { return crc_; }

 private:
  std::uint16_t crc_ = 0xFFFF;
};

}  // namespace accelcal::mavlink
