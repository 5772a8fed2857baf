#include "accelcal/io/recording_reader.h"

#include <algorithm>

#include "accelcal/io/recording_stream.h"

namespace accelcal {
namespace {

constexpr size_t kShortLineBytes = 24;          // "0.01 33096 33336 36437" and its newline
constexpr size_t kMaxFirstReserve = size_t{1} << 16;  // samples, before the first block is seen

}  // namespace

Recording ReadRecording(const std::string& path, const SampleFormat& format) {
  RecordingStream stream(path, RecordingStream::kDefaultBlockBytes, format);
  Recording out;
  // Reserved from the file's size rather than a vector doubling its way up (each doubling
  // copies every sample and faults in new pages): first for lines of kShortLineBytes (pages
  // reserved and never written cost no memory), then from the first block's own line length.
  // Not on transparent huge pages: with the kernel's "madvise" defragmentation a large
  // reservation then waits on compaction at its first faults (reading the 96 MB 1-hour record
  // took 650 ms instead of 350 on this project's machine; no gain on the small Xsens file).
  if (stream.expected_samples() > 0)
    out.samples.reserve(static_cast<size_t>(stream.expected_samples()));  // a bag's index
  else if (stream.size_hint() > 0)
    out.samples.reserve(std::min(stream.size_hint() / kShortLineBytes, kMaxFirstReserve) + 1024);
  if (!stream.AppendNext(&out.samples)) {
    out.summary = stream.Summary();
    return out;
  }
  if (stream.size_hint() > stream.bytes_read() && !out.samples.empty()) {
    const double bytes_per_sample =
        static_cast<double>(stream.bytes_read()) / static_cast<double>(out.samples.size());
    const double expected = static_cast<double>(stream.size_hint()) / bytes_per_sample;
    out.samples.reserve(static_cast<size_t>(expected * 1.02) + 1024);
  }
  while (stream.AppendNext(&out.samples)) {
  }
  out.summary = stream.Summary();
  return out;
}

Recording ParseRecordingText(std::string_view text, const std::string& source_name,
                             const SampleFormat& format) {
  SampleReader reader(source_name, format, SampleReader::OnMalformed::kThrow);
  Recording out;
  reader.Consume(text, /*final=*/true, &out.samples);
  reader.Finish(&out.samples);
  out.summary = reader.Summary();
  return out;
}

std::vector<Sample> ReadRecordingFile(const std::string& path) {
  return ReadRecording(path).samples;
}

std::vector<Sample> ParseRecording(std::string_view text, const std::string& source_name) {
  return ParseRecordingText(text, source_name).samples;
}

}  // namespace accelcal
