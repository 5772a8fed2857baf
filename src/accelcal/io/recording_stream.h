// Reading a recording block by block, for records too long to hold in memory (12 hours at
// 1 kHz is 43 million lines, ~1.7 GB of text), and for the whole-file reader
// (recording_reader.h), which appends every block. The format is the sample reader's
// (base/sample_reader.h: columns, header, skipped rows, rate, repaired time stamps); errors name
// FILE:LINE:COLUMN. Memory is bounded by the block size plus the longest line allowed.
//
// Speed: each block is read with read(2) straight into one buffer allocated once (never
// zero-filled), parsed in place, and only the partial line at its end is moved to the front.
//
// A ROS bag (a ROS 1 .bag, an .mcap or .db3 file, a ROS 2 bag folder: bags/bag_open.h) is read
// by the bag reader instead (bags/bag_sample_stream.h), one chunk at a time: the samples of its
// IMU topic, through the same time checks, in m/s^2.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "accelcal/bags/bag_sample_stream.h"
#include "accelcal/base/capture.h"
#include "accelcal/base/sample_format.h"
#include "accelcal/base/sample_reader.h"

namespace accelcal {

class RecordingStream {
 public:
  // 256 KiB: the buffer stays in the cache and is faulted in once (a 4 MiB one cost a page
  // fault per 4 KiB of every file smaller than it, a quarter of `fit --recording`'s time on the
  // 3.3 MB Xsens file); the system calls per MB are still few.
  static constexpr size_t kDefaultBlockBytes = size_t{1} << 18;

  // Opens `path` ("-" is standard input). Throws accelcal::Error "cannot open 'PATH': <reason>",
  // or for an invalid format (a bag's choice given for a text: --topic, --bag-time; a table's
  // options given for a bag; a bag's refusals, bags/bag_topics.h). `block_bytes` > 0 is how
  // much text is read at a time.
  explicit RecordingStream(const std::string& path, size_t block_bytes = kDefaultBlockBytes,
                           const SampleFormat& format = {});
  ~RecordingStream();
  RecordingStream(const RecordingStream&) = delete;
  RecordingStream& operator=(const RecordingStream&) = delete;

  // Replaces *samples with the next samples of the file, in file order; false (and *samples
  // empty) once the file is exhausted. Malformed content throws accelcal::InputError
  // (FILE:LINE:COLUMN), read failures accelcal::Error; the samples returned before stay valid.
  bool Next(std::vector<Sample>* samples);
  // As Next, but appends to *samples; false once nothing more was appended (exhausted).
  bool AppendNext(std::vector<Sample>* samples);

  const std::string& path() const { return path_; }
  // The size of the file when known (0 for a pipe), bytes; for reserving.
  size_t size_hint() const { return size_hint_; }
  // Bytes read so far.
  size_t bytes_read() const { return bytes_read_; }
  // What the reading understood so far (complete once Next returned false).
  ReadingSummary Summary() const { return bag_ ? bag_->Summary() : reader_.Summary(); }
  // What the readings are in: the format's unit, or a bag's m/s^2.
  const ReadingUnit& unit() const { return bag_ ? bag_->format().unit : reader_unit_; }
  // The samples to expect when known before reading (a bag's indexed message count), else -1.
  long long expected_samples() const { return bag_ ? bag_->choice().messages : -1; }
  bool is_bag() const { return bag_ != nullptr; }

 private:
  bool Fill();  // reads one block after the kept partial line; false at end of file

  std::string path_;
  int fd_ = -1;
  bool owns_fd_ = false;
  size_t block_bytes_;
  std::unique_ptr<char[]> buffer_;  // capacity_ bytes, uninitialised
  size_t capacity_ = 0;
  size_t used_ = 0;                 // bytes in buffer_: a partial line, then a block
  size_t size_hint_ = 0;
  size_t bytes_read_ = 0;
  bool at_eof_ = false;
  bool finished_ = false;
  SampleReader reader_;
  ReadingUnit reader_unit_;
  std::unique_ptr<bags::BagSampleStream> bag_;
};

}  // namespace accelcal
