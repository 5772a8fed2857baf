#include "accelcal/bags/chunk_codec.h"

#include <bzlib.h>
#include <lz4frame.h>
#include <zstd.h>

#include <climits>

#include <fmt/format.h>

#include "accelcal/base/error.h"

namespace accelcal::bags {

std::optional<ChunkCodec> ChunkCodecNamed(std::string_view name) {
  if (name.empty() || name == "none") return ChunkCodec::kNone;
  if (name == "zstd") return ChunkCodec::kZstd;
  if (name == "lz4") return ChunkCodec::kLz4;
  if (name == "bz2") return ChunkCodec::kBz2;
  return std::nullopt;
}

std::string_view ChunkCodecName(ChunkCodec codec) {
  switch (codec) {
    case ChunkCodec::kNone: return "uncompressed";
    case ChunkCodec::kZstd: return "zstd";
    case ChunkCodec::kLz4: return "lz4";
    case ChunkCodec::kBz2: return "bz2";
  }
  return "uncompressed";
}

ChunkDecompressor::ChunkDecompressor() {
  zstd_ = ZSTD_createDCtx();
  LZ4F_dctx* lz4 = nullptr;
  if (zstd_ == nullptr || LZ4F_isError(LZ4F_createDecompressionContext(&lz4, LZ4F_VERSION)))
    throw Error("cannot set up the chunk decompressors (out of memory)");
  lz4_ = lz4;
}

ChunkDecompressor::~ChunkDecompressor() {
  ZSTD_freeDCtx(static_cast<ZSTD_DCtx*>(zstd_));
  LZ4F_freeDecompressionContext(static_cast<LZ4F_dctx*>(lz4_));
}

ChunkDecompressor::Result ChunkDecompressor::Run(ChunkCodec codec, const uint8_t* in,
                                                 size_t in_size, uint8_t* out, size_t capacity,
                                                 bool whole_input) {
  switch (codec) {
    case ChunkCodec::kNone: {
      Result r;
      r.produced = std::min(in_size, capacity);
      std::copy(in, in + r.produced, out);
      r.complete = whole_input && in_size <= capacity;
      if (in_size > capacity) r.error = "more bytes than the chunk declares";
      return r;
    }
    case ChunkCodec::kZstd: return Zstd(in, in_size, out, capacity, whole_input);
    case ChunkCodec::kLz4: return Lz4(in, in_size, out, capacity);
    case ChunkCodec::kBz2: return Bz2(in, in_size, out, capacity);
  }
  return {};
}

ChunkDecompressor::Result ChunkDecompressor::Zstd(const uint8_t* in, size_t in_size, uint8_t* out,
                                                  size_t capacity, bool whole_input) {
  auto* dctx = static_cast<ZSTD_DCtx*>(zstd_);
  Result r;
  if (whole_input) {
    // The common case in one call, straight into the output (no window copy).
    const size_t got = ZSTD_decompressDCtx(dctx, out, capacity, in, in_size);
    if (!ZSTD_isError(got)) {
      r.produced = got;
      r.complete = true;
      return r;
    }
    // Corrupt or not one whole frame: the streaming decoder below says how far it gets.
  }
  ZSTD_DCtx_reset(dctx, ZSTD_reset_session_only);
  ZSTD_inBuffer input{in, in_size, 0};
  ZSTD_outBuffer output{out, capacity, 0};
  while (input.pos < input.size) {
    const size_t ret = ZSTD_decompressStream(dctx, &output, &input);
    if (ZSTD_isError(ret)) {
      r.error = fmt::format("zstd: {}", ZSTD_getErrorName(ret));
      break;
    }
    if (ret == 0) {
      r.complete = true;
      if (input.pos < input.size) r.error = "bytes after the end of the zstd frame";
      break;
    }
    if (output.pos == output.size) {
      r.error = "more bytes than the chunk declares";
      break;
    }
  }
  r.produced = output.pos;
  return r;
}

ChunkDecompressor::Result ChunkDecompressor::Lz4(const uint8_t* in, size_t in_size, uint8_t* out,
                                                 size_t capacity) {
  auto* dctx = static_cast<LZ4F_dctx*>(lz4_);
  LZ4F_resetDecompressionContext(dctx);
  Result r;
  size_t in_pos = 0;
  size_t out_pos = 0;
  while (in_pos < in_size) {
    size_t out_left = capacity - out_pos;
    size_t in_left = in_size - in_pos;
    const size_t ret = LZ4F_decompress(dctx, out + out_pos, &out_left, in + in_pos, &in_left, nullptr);
    in_pos += in_left;
    out_pos += out_left;
    if (LZ4F_isError(ret)) {
      r.error = fmt::format("lz4: {}", LZ4F_getErrorName(ret));
      break;
    }
    if (ret == 0) {
      r.complete = true;
      if (in_pos < in_size) r.error = "bytes after the end of the lz4 frame";
      break;
    }
    if (in_left == 0 && out_left == 0) {
      if (out_pos == capacity) r.error = "more bytes than the chunk declares";
      break;  // no progress: the decoder wants more input than there is
    }
  }
  r.produced = out_pos;
  return r;
}

ChunkDecompressor::Result ChunkDecompressor::Bz2(const uint8_t* in, size_t in_size, uint8_t* out,
                                                 size_t capacity) {
  Result r;
  bz_stream s{};
  if (BZ2_bzDecompressInit(&s, 0, 0) != BZ_OK) {
    r.error = "bz2: cannot start the decompressor";
    return r;
  }
  size_t in_pos = 0;
  size_t out_pos = 0;
  // bzlib counts in unsigned int: feed it in pieces below that.
  constexpr size_t kPiece = UINT_MAX / 2;
  for (;;) {
    const size_t in_take = std::min(in_size - in_pos, kPiece);
    const size_t out_take = std::min(capacity - out_pos, kPiece);
    s.next_in = const_cast<char*>(reinterpret_cast<const char*>(in + in_pos));
    s.avail_in = static_cast<unsigned>(in_take);
    s.next_out = reinterpret_cast<char*>(out + out_pos);
    s.avail_out = static_cast<unsigned>(out_take);
    const int ret = BZ2_bzDecompress(&s);
    in_pos += in_take - s.avail_in;
    out_pos += out_take - s.avail_out;
    if (ret == BZ_STREAM_END) {
      r.complete = true;
      break;
    }
    if (ret != BZ_OK) {
      r.error = fmt::format("bz2: the data is corrupt (error {})", ret);
      break;
    }
    if (out_pos == capacity && s.avail_out == 0) {
      r.error = "more bytes than the chunk declares";
      break;
    }
    if (in_pos == in_size) break;  // the input stopped inside the stream (a cut file)
  }
  BZ2_bzDecompressEnd(&s);
  r.produced = out_pos;
  return r;
}

}  // namespace accelcal::bags
