// Little-endian binary fields (MCAP records, ROS 1 bag records, CDR and ROS 1 messages) read
// from a bounded span. Every read is checked against the span's end: a cut file or a corrupt
// length never reads past it, it only makes the reader fail (ok() false), and the caller says
// what was cut.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace accelcal::bags {

// std::byteswap is C++23; GCC 12 has the builtins.
inline uint16_t SwapBytes(uint16_t v) { return __builtin_bswap16(v); }
inline uint32_t SwapBytes(uint32_t v) { return __builtin_bswap32(v); }
inline uint64_t SwapBytes(uint64_t v) { return __builtin_bswap64(v); }
inline int32_t SwapBytes(int32_t v) { return static_cast<int32_t>(__builtin_bswap32(static_cast<uint32_t>(v))); }

// The value of the bytes at `p` in little-endian order (unaligned access is fine).
template <typename T>
inline T LoadLittle(const uint8_t* p) {
  T value;
  std::memcpy(&value, p, sizeof value);
  if constexpr (std::endian::native == std::endian::big) value = SwapBytes(value);
  return value;
}

// The same in big-endian order (CDR_BE messages).
template <typename T>
inline T LoadBig(const uint8_t* p) {
  T value;
  std::memcpy(&value, p, sizeof value);
  if constexpr (std::endian::native == std::endian::little) value = SwapBytes(value);
  return value;
}

inline double LoadDouble(const uint8_t* p, bool big_endian) {
  const uint64_t bits = big_endian ? LoadBig<uint64_t>(p) : LoadLittle<uint64_t>(p);
  return std::bit_cast<double>(bits);
}

class ByteReader {
 public:
  ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  // False once a read wanted more bytes than were left (every later read returns zeros).
  bool ok() const { return ok_; }
  size_t offset() const { return pos_; }
  size_t remaining() const { return size_ - pos_; }
  const uint8_t* here() const { return data_ + pos_; }

  uint8_t U8() { return Need(1) ? data_[pos_++] : 0; }
  uint16_t U16() { return Take<uint16_t>(); }
  uint32_t U32() { return Take<uint32_t>(); }
  uint64_t U64() { return Take<uint64_t>(); }
  // A uint32 byte length and that many bytes (MCAP's String and uint32-prefixed Bytes).
  std::string_view String() { return Bytes(U32()); }
  std::string_view Bytes(uint64_t n) {
    if (!Need(n)) return {};
    const std::string_view out(reinterpret_cast<const char*>(data_ + pos_), static_cast<size_t>(n));
    pos_ += static_cast<size_t>(n);
    return out;
  }
  void Skip(uint64_t n) {
    if (Need(n)) pos_ += static_cast<size_t>(n);
  }

 private:
  bool Need(uint64_t n) {
    if (ok_ && n <= size_ - pos_) return true;
    ok_ = false;
    pos_ = size_;
    return false;
  }
  template <typename T>
  T Take() {
    if (!Need(sizeof(T))) return 0;
    const T v = LoadLittle<T>(data_ + pos_);
    pos_ += sizeof(T);
    return v;
  }

  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
  bool ok_ = true;
};

}  // namespace accelcal::bags
