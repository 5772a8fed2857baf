#include "accelcal/io/recording_reader.h"

#include <algorithm>

#include "accelcal/io/detail/read_file.h"
#include "accelcal/io/detail/recording_lines.h"
#include "accelcal/base/sample_line_parser.h"
#include "accelcal/base/text_scan.h"
#include "accelcal/base/error.h"

namespace accelcal {
namespace {

std::vector<Sample> ParseLines(std::string_view text, const std::string& source_name) {
  detail::SampleLineParser parser(source_name);
  std::vector<Sample> samples;
  // One sample per line at most: reserve once instead of growing.
  samples.reserve(static_cast<size_t>(std::count(text.begin(), text.end(), '\n')) + 1);
  long line_number = 0;
  detail::ParseRecordingLines(text, /*final=*/true, parser, &line_number, &samples);
  return samples;
}

}  // namespace

std::vector<Sample> ReadRecordingFile(const std::string& path) {
  return ParseRecording(detail::ReadWholeFile(path), path);
}

std::vector<Sample> ParseRecording(std::string_view text, const std::string& source_name) {
  return ParseLines(detail::StripBom(text), source_name);
}

}  // namespace accelcal
