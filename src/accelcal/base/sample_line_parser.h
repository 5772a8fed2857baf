// One line of the sample protocol `t ax ay az [temp_c]` (blanks and/or one comma between
// fields, '#' comments, blank lines), with the checks that span lines: every data line has the
// field count of the first one, and t increases strictly. Shared by the recording reader (a
// whole file) and `accelcal apply` (a stream, line by line). Internal to src/.
#pragma once

#include <string>
#include <string_view>

#include "accelcal/base/capture.h"

namespace accelcal::detail {

class SampleLineParser {
 public:
  explicit SampleLineParser(std::string source_name) : source_name_(std::move(source_name)) {}

  // Parses `line` (no terminator), the `line_number`-th (1-based) of the source. Returns false
  // for a comment or blank line; true with *sample filled for a data line. A malformed line
  // throws InputError naming the line and column, and leaves the parser's state as it was, so
  // a caller may report it and go on with the next line.
  bool Parse(std::string_view line, long line_number, Sample* sample);

 private:
  const char* ParseField(const char* p, const char* begin, const char* end, int index,
                         double* value) const;
  const char* SkipSeparator(const char* p, const char* begin, const char* end) const;
  void CheckFieldCount(int count, const char* begin, const char* end) const;
  void CheckTime(double t_s, const char* t_begin, const char* begin, const char* end) const;
  [[noreturn]] void Fail(const char* begin, const char* end, const char* at,
                         const std::string& message) const;

  std::string source_name_;
  long line_number_ = 0;       // of the line being parsed
  int fields_per_line_ = 0;    // set by the first data line
  long first_data_line_ = 0;
  bool has_previous_ = false;
  double previous_t_s_ = 0.0;
  long previous_t_line_ = 0;
};

}  // namespace accelcal::detail
