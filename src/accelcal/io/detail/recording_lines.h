// The line loop of the recording format (io/recording_reader.h), shared by the whole-file reader
// and the block-by-block stream: it walks complete lines straight from a buffer (no copies, no
// allocation per line) and hands each to a SampleLineParser. Internal to src/.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/sample_line_parser.h"

namespace accelcal::detail {

// Parses the lines of `text` and appends their samples to `out`. Only lines ended by '\n' are
// parsed, unless `final` (the end of the input), when a last unterminated line is parsed too.
// `*line_number` is the number of the line before `text`'s first, and is advanced past every
// line parsed. Returns the bytes consumed: the caller keeps the rest (a partial line) for the
// next call. Malformed lines throw the parser's InputError.
size_t ParseRecordingLines(std::string_view text, bool final, SampleLineParser& parser,
                           long* line_number, std::vector<Sample>* out);

}  // namespace accelcal::detail
