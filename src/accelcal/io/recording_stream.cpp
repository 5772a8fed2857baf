#include "accelcal/io/recording_stream.h"

#include <cerrno>
#include <cstring>

#include "accelcal/io/detail/recording_lines.h"
#include "accelcal/base/text_scan.h"
#include "accelcal/base/error.h"

namespace accelcal {

RecordingStream::RecordingStream(const std::string& path, size_t block_bytes)
    : path_(path), block_bytes_(block_bytes), parser_(path) {
  if (block_bytes_ == 0) throw Error("RecordingStream: block_bytes must be > 0");
  if (path == "-") {
    file_ = stdin;
    return;
  }
  file_ = std::fopen(path.c_str(), "rb");
  if (file_ == nullptr)
    throw Error("cannot open '" + path + "': " + std::strerror(errno));
  owns_file_ = true;
}

RecordingStream::~RecordingStream() {
  if (owns_file_) std::fclose(file_);
}

bool RecordingStream::Fill() {
  if (at_eof_) return false;
  const size_t used = buffer_.size();
  buffer_.resize(used + block_bytes_);
  const size_t got = std::fread(buffer_.data() + used, 1, block_bytes_, file_);
  buffer_.resize(used + got);
  if (got < block_bytes_) {
    if (std::ferror(file_)) throw Error("cannot read '" + path_ + "': " + std::strerror(errno));
    at_eof_ = true;
  }
  if (first_block_ && (buffer_.size() >= 3 || at_eof_)) {
    // The byte-order mark can only be at the very start of the file (decided once its three
    // bytes are in, however small the blocks).
    const std::string_view stripped = detail::StripBom(buffer_);
    buffer_.erase(0, buffer_.size() - stripped.size());
    first_block_ = false;
  }
  return got > 0;
}

bool RecordingStream::Next(std::vector<Sample>* samples) {
  samples->clear();
  // Read until at least one sample is parsed or the file ends (a block may hold only comments,
  // or only part of one long line).
  while (samples->empty()) {
    const bool more = Fill();
    const size_t consumed =
        detail::ParseRecordingLines(buffer_, /*final=*/!more, parser_, &line_number_, samples);
    buffer_.erase(0, consumed);
    if (consumed > 0) first_block_ = false;  // past the start: no byte-order mark any more
    if (!more) return !samples->empty();
  }
  return true;
}

}  // namespace accelcal
