#include "accelcal/io/recording_reader.h"

#include <algorithm>
#include <cstring>


#include "accelcal/detail/read_file.h"
#include "accelcal/detail/sample_line_parser.h"
#include "accelcal/detail/text_scan.h"
#include "accelcal/error.h"

namespace accelcal {
namespace {

// Walks the text line by line straight from the buffer (no copies, no allocation per line).
std::vector<Sample> ParseLines(std::string_view text, const std::string& source_name) {
  detail::SampleLineParser parser(source_name);
  std::vector<Sample> samples;
  const char* p = text.data();
  const char* const end = p + text.size();
  // One sample per line at most: reserve once instead of growing.
  samples.reserve(static_cast<size_t>(std::count(p, end, '\n')) + 1);
  long line_number = 0;
  Sample sample;
  while (p < end) {
    ++line_number;
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p)));
    if (eol == nullptr) eol = end;
    const char* line_end = (eol > p && eol[-1] == '\r') ? eol - 1 : eol;
    if (parser.Parse(std::string_view(p, static_cast<size_t>(line_end - p)), line_number, &sample))
      samples.push_back(sample);
    p = eol + 1;
  }
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
