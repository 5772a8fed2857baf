// Reading a continuous recording into memory: one sample per line, as logged by a data logger
// or exported by other tools (the imu_tk test data, tests/data/imu_tk/xsens_acc.mat, is
// one). The reader is the one of every sample table (base/sample_reader.h; docs/formats.md,
// "Reading other people's files"); the protocol's form, with no options, is:
//
//   # comment
//      2.9840000e-02   3.3108000e+04   3.3329000e+04   3.6429000e+04
//   0.03987, 33096, 33336, 36437, 24.5
//
// - Each data line is `t ax ay az [temp_c]`: t in s, ax ay az raw readings in ADC counts,
//   temp_c in degC. Fields are separated by blanks (spaces, tabs) and/or one comma or one
//   semicolon; leading and trailing blanks are ignored. All data lines have the same number of
//   fields (4 or 5) as the first one.
// - Lines whose first non-blank character is '#' are comments; blank lines are skipped.
//   Line endings may be LF or CRLF; a UTF-8 byte-order mark at the start is skipped.
// - Every value must be a finite number (a recording feeds the static detector, whose running
//   sums a single NaN would spoil), and t must increase (stamps rounded by the logger are
//   spread within their step: base/sample_time_check.h).
// - A SampleFormat names other columns (or a header row does), skips leading rows, gives the
//   rate when there is no time column, and the unit of readings already converted.
//
// Errors: accelcal::InputError naming the file, the 1-based line and the 1-based column of the
// offending field, e.g. "rec.txt:7:18: field 'ay': '3.3e+0x4' is not a number".
//
// Speed: blocks are read into one reused buffer and parsed in place with std::from_chars, with
// no allocation per line; the samples are reserved from the file's size; bench/recording_reader_bench.cpp
// measures it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/sample_format.h"
#include "accelcal/base/sample_reader.h"

namespace accelcal {

struct Recording {
  std::vector<Sample> samples;  // in file order; temp_c NaN without a temperature column
  ReadingSummary summary;       // what was understood (its Describe() is the one line to show)
};

// Reads and parses the file at `path` ("-": standard input; source_name = path).
// Throws accelcal::Error "cannot open 'PATH': <reason>" when it cannot be read (or for an
// invalid format), and accelcal::InputError for malformed content.
Recording ReadRecording(const std::string& path, const SampleFormat& format = {});

// Parses `text`, a whole recording; `source_name` names it in messages.
Recording ParseRecordingText(std::string_view text, const std::string& source_name,
                             const SampleFormat& format = {});

// The samples alone, in the protocol's form (no options).
std::vector<Sample> ReadRecordingFile(const std::string& path);
std::vector<Sample> ParseRecording(std::string_view text, const std::string& source_name);

}  // namespace accelcal
