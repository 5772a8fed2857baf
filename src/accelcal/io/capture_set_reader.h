// Reading a capture-set file: the raw samples of several captures (static poses and turntable
// runs) in one CSV table.
//
// Format (one sample per row):
//
//   # adc_range_counts = 0,4095          <- optional metadata (sets CaptureSet::adc_range)
//   # any other comment
//   capture,kind,t,ax,ay,az,temp_c,radius_m,rpm,label,up_axis
//   1,static,0.00,2051,2013,2934,24.1,,,"z up, on the granite"
//   1,static,0.01,2050,2012,2935,24.1,,,"z up, on the granite"
//   2,turntable,12.50,2040,2790,2930,,0.15,60,spin 60 rpm
//
// - Lines whose first non-blank character is '#' are comments; blank lines are ignored. Both
//   may appear anywhere. A comment that is exactly "adc_range_counts = MIN,MAX" (blanks allowed
//   around each token; MIN < MAX, finite, counts, inclusive) is metadata; a malformed one, or a
//   second one, is an error.
// - The first other line is the header. It names the columns in any order. Required:
//   capture, kind, t, ax, ay, az. Optional: temp_c, radius_m, rpm, label, up_axis, up. t, ax,
//   ay, az and temp_c are also recognised in the common spellings of sample tables
//   (base/sample_columns.h: time, acc_x, AccX, accel_x, temperature, ...). Unknown and repeated
//   names are errors.
// - capture: integer id (0 .. INT_MAX). The rows of one capture are contiguous.
// - kind: "static" or "turntable"; kind, radius_m, rpm, label, up_axis and up are the same on all
//   rows of a capture.
// - t: seconds, finite, never decreasing down the file (one session clock).
// - ax, ay, az: raw readings, ADC counts. "nan" and "inf" are accepted (any case): they are
//   read as non-finite values so that screening (capture_screening.h) rejects the capture with
//   a reason, instead of the whole file failing.
// - temp_c: degC; empty or "nan" means unknown (NaN).
// - radius_m (m) and rpm (revolutions per minute): required on turntable rows (finite, > 0);
//   empty or absent on static rows.
// - up_axis: turntable rows only, optional: the sensor axis that pointed up ("+x" ... "-z").
// - up: static rows only, optional: the up direction the procedure asked for, sensor frame:
//   "+x" ... "-z", or three numbers separated by blanks ("0.577 0.577 -0.577"; normalized).
// - label: free text. RFC 4180 quoting when it holds commas: "a, b" and "say ""hi""".
//   A quoted field cannot span lines.
// - Blanks around fields are ignored. Line endings may be LF or CRLF; a UTF-8 byte-order mark
//   at the start is skipped.
//
// Errors: every malformed line throws accelcal::InputError naming the file, the 1-based line and
// the 1-based column (in characters) where the offending field starts, e.g.
//   "set.csv:14:9: column 'ax': 'abc' is not a number".
// A missing header column is reported at column 1 of the header; an empty file (or one with
// only comments) at line 0; a file with a header but no data rows at the header's line.
#pragma once

#include <string>
#include <string_view>

#include "accelcal/base/capture_set.h"

namespace accelcal {

// Reads and parses the file at `path` (source_name = path).
// Throws accelcal::Error "cannot open 'PATH': <reason>" when it cannot be read, and
// accelcal::InputError for malformed content.
CaptureSet ReadCaptureSetFile(const std::string& path);

// Parses `text`, a whole capture-set file; `source_name` names it in messages and is stored
// in CaptureSet::source_name. Captures come out in file order, unscreened
// (rejection_reason empty). Throws accelcal::InputError for malformed content.
CaptureSet ParseCaptureSet(std::string_view text, const std::string& source_name);

}  // namespace accelcal
