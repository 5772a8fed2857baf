// An IIO scan element's type, as the kernel writes it in scan_elements/in_X_type (the IIO sysfs
// ABI, Documentation/ABI/testing/sysfs-bus-iio, "scan_elements/in_..._type"; libiio reads the
// same string):
//
//   [be|le]:[s|u]BITS/STORAGEBITS[Xrepeat]>>SHIFT        e.g. le:s12/16>>4, be:u10/16>>0, le:s16/16X3>>0
//
// A value takes STORAGEBITS bits in the buffer (8, 16, 32 or 64), in that byte order; shifted
// right by SHIFT, its low BITS bits are the reading, sign-extended when signed. libiio prints the
// sign letter in capitals (S, U); both are read.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace accelcal {

struct IioScanType {
  bool big_endian = false;
  bool is_signed = false;
  int bits = 0;          // real bits
  int storage_bits = 0;  // 8, 16, 32, 64
  int shift = 0;
  int repeat = 1;

  int StorageBytes() const { return storage_bits / 8; }
  // Bytes the element takes in a record (repeats included).
  int ElementBytes() const { return StorageBytes() * repeat; }
  // The first value of the element that starts at `bytes`.
  std::int64_t Decode(const std::uint8_t* bytes) const;
  // "le:s12/16>>4".
  std::string Describe() const;
};

// nullopt, with *why saying what is not understood, for anything else.
std::optional<IioScanType> ParseIioScanType(std::string_view text, std::string* why);

}  // namespace accelcal
