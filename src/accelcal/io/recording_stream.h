// Reading a continuous recording block by block, for records too long to hold in memory (12 hours
// at 1 kHz is 43 million lines, ~1.7 GB of text). Same format, same checks and same errors as
// recording_reader.h, which reads a whole file at once; memory is bounded by the block size
// (plus the longest line).
#pragma once

#include <cstddef>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/sample_line_parser.h"

namespace accelcal {

class RecordingStream {
 public:
  // Opens `path` ("-" is standard input). Throws accelcal::Error "cannot open 'PATH': <reason>".
  // `block_bytes` > 0 is how much is read at a time.
  explicit RecordingStream(const std::string& path, size_t block_bytes = size_t{1} << 22);
  ~RecordingStream();
  RecordingStream(const RecordingStream&) = delete;
  RecordingStream& operator=(const RecordingStream&) = delete;

  // Replaces *samples with the next samples of the file, in file order; false (and *samples
  // empty) once the file is exhausted. Malformed content throws accelcal::InputError
  // (FILE:LINE:COLUMN), read failures accelcal::Error; the samples returned before stay valid.
  bool Next(std::vector<Sample>* samples);

  const std::string& path() const { return path_; }

 private:
  bool Fill();  // reads more bytes into buffer_; false at end of file

  std::string path_;
  std::FILE* file_ = nullptr;  // owned unless it is stdin
  bool owns_file_ = false;
  size_t block_bytes_;
  std::string buffer_;   // unparsed bytes: at most a partial line between calls
  bool at_eof_ = false;
  bool first_block_ = true;  // the byte-order mark is still to be looked for
  long line_number_ = 0;
  detail::SampleLineParser parser_;
};

}  // namespace accelcal
