#include "accelcal/io/detail/recording_lines.h"

#include <cstring>

namespace accelcal::detail {

size_t ParseRecordingLines(std::string_view text, bool final, SampleLineParser& parser,
                           long* line_number, std::vector<Sample>* out) {
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  const char* p = begin;
  Sample sample;
  while (p < end) {
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p)));
    if (eol == nullptr) {
      if (!final) break;  // a partial line: wait for the rest
      eol = end;
    }
    ++*line_number;
    const char* line_end = (eol > p && eol[-1] == '\r') ? eol - 1 : eol;
    if (parser.Parse(std::string_view(p, static_cast<size_t>(line_end - p)), *line_number, &sample))
      out->push_back(sample);
    p = eol < end ? eol + 1 : end;
  }
  return static_cast<size_t>(p - begin);
}

}  // namespace accelcal::detail
