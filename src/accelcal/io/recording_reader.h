// Reading a continuous recording: one sample per line, as logged by a data logger or exported by
// other tools (the imu_tk test data, /work/shared/data/imu_tk/xsens_acc.mat, is one).
//
// Format:
//
//   # comment
//      2.9840000e-02   3.3108000e+04   3.3329000e+04   3.6429000e+04
//   0.03987, 33096, 33336, 36437, 24.5
//
// - Each data line is `t ax ay az [temp_c]`: t in s, ax ay az raw readings in ADC counts,
//   temp_c in degC. Fields are separated by blanks (spaces, tabs) and/or one comma; leading and
//   trailing blanks are ignored. All data lines have the same number of fields (4 or 5) as the
//   first one.
// - Lines whose first non-blank character is '#' are comments; blank lines are skipped.
//   Line endings may be LF or CRLF; a UTF-8 byte-order mark at the start is skipped.
// - Every value must be a finite number (a recording feeds the static detector, whose running
//   sums a single NaN would spoil), and t must be strictly increasing.
//
// Errors: accelcal::InputError naming the file, the 1-based line and the 1-based column of the
// offending field, e.g. "rec.txt:7:18: field 'ay': '3.3e+0x4' is not a number".
//
// Speed: the file is read in one go and parsed in place with std::from_chars, with no
// allocation per line; bench/recording_reader_bench.cpp measures it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "accelcal/base/capture.h"

namespace accelcal {

// Reads and parses the file at `path` (source_name = path).
// Throws accelcal::Error "cannot open 'PATH': <reason>" when it cannot be read, and
// accelcal::InputError for malformed content.
std::vector<Sample> ReadRecordingFile(const std::string& path);

// Parses `text`, a whole recording; `source_name` names it in messages. Samples come out in
// file order; temp_c is NaN when the lines have 4 fields.
std::vector<Sample> ParseRecording(std::string_view text, const std::string& source_name);

}  // namespace accelcal
