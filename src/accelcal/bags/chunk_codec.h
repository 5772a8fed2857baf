// The compressions of bag chunks, through Debian's libraries: zstd and lz4 (MCAP chunks, the
// LZ4 frame format), bz2 and lz4 (ROS 1 chunks: roslz4 writes standard LZ4 frames), and none.
//
// A cut file ends inside its last chunk: that chunk's compressed bytes are a prefix of a
// frame. It is decompressed as far as its bytes go (streaming), so the messages it holds up to
// the cut are still read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace accelcal::bags {

enum class ChunkCodec { kNone, kZstd, kLz4, kBz2 };

// "" and "none" -> kNone, "zstd", "lz4", "bz2"; nullopt for any other name.
std::optional<ChunkCodec> ChunkCodecNamed(std::string_view name);
std::string_view ChunkCodecName(ChunkCodec codec);

class ChunkDecompressor {
 public:
  ChunkDecompressor();
  ~ChunkDecompressor();
  ChunkDecompressor(const ChunkDecompressor&) = delete;
  ChunkDecompressor& operator=(const ChunkDecompressor&) = delete;

  struct Result {
    size_t produced = 0;    // bytes written to the output
    bool complete = false;  // the frame ended (false: the input stopped first, or a frame error)
    std::string error;      // the codec's words for corrupt data; empty when none
  };

  // Decompresses `in` (a whole frame when `whole_input`, else the prefix a cut file left) into
  // out[0, capacity). Output beyond `capacity` (more than the chunk declared) is an error.
  // Never throws for bad data: the error is in the result, with what was produced before it.
  Result Run(ChunkCodec codec, const uint8_t* in, size_t in_size, uint8_t* out, size_t capacity,
             bool whole_input);

 private:
  Result Zstd(const uint8_t* in, size_t in_size, uint8_t* out, size_t capacity, bool whole_input);
  Result Lz4(const uint8_t* in, size_t in_size, uint8_t* out, size_t capacity);
  Result Bz2(const uint8_t* in, size_t in_size, uint8_t* out, size_t capacity);

  void* zstd_ = nullptr;  // ZSTD_DCtx, reused
  void* lz4_ = nullptr;   // LZ4F_dctx, reused
};

}  // namespace accelcal::bags
