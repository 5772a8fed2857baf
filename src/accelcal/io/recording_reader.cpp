#include "accelcal/io/recording_reader.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "accelcal/detail/read_file.h"
#include "accelcal/detail/text_scan.h"
#include "accelcal/error.h"

namespace accelcal {
namespace {

constexpr int kMinFields = 4;
constexpr int kMaxFields = 5;
constexpr std::array<std::string_view, kMaxFields> kFieldNames = {"t", "ax", "ay", "az",
                                                                   "temp_c"};

inline bool IsSeparatorChar(char c) { return c == ' ' || c == '\t' || c == ','; }

// Parses the recording line by line, straight from the text buffer (no copies, no allocation
// per line). Errors are built only on the failure path.
class RecordingParser {
 public:
  RecordingParser(std::string_view text, const std::string& source_name)
      : text_(detail::StripBom(text)), source_name_(source_name) {}

  std::vector<Sample> Run();

 private:
  // Parses one line [begin, end) into `samples_` (comments and blank lines add nothing).
  void ParseLine(const char* begin, const char* end);
  // Parses the number starting at `p`; returns the position just after it.
  const char* ParseField(const char* p, const char* line_begin, const char* end, int index,
                         double* value) const;
  // Skips the separator after a field: blanks, at most one comma, blanks.
  const char* SkipSeparator(const char* p, const char* line_begin, const char* end) const;
  void CheckFieldCount(int count, const char* line_begin, const char* end) const;
  void CheckTime(double t_s, const char* t_begin, const char* line_begin,
                 const char* end) const;

  [[noreturn]] void Fail(const char* line_begin, const char* end, const char* at,
                         const std::string& message) const {
    const std::string_view line(line_begin, static_cast<size_t>(end - line_begin));
    throw InputError(source_name_, line_number_,
                     detail::ColumnAt(line, static_cast<size_t>(at - line_begin)), message);
  }

  std::string_view text_;
  const std::string& source_name_;  // borrowed: outlives the parser (a Parse call)
  std::vector<Sample> samples_;
  long line_number_ = 0;
  int fields_per_line_ = 0;  // set by the first data line
  long first_data_line_ = 0;
  long previous_t_line_ = 0;
};

std::vector<Sample> RecordingParser::Run() {
  const char* p = text_.data();
  const char* const end = p + text_.size();
  // One sample per line at most: reserve once instead of growing.
  samples_.reserve(static_cast<size_t>(std::count(p, end, '\n')) + 1);
  while (p < end) {
    ++line_number_;
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p)));
    if (eol == nullptr) eol = end;
    const char* line_end = (eol > p && eol[-1] == '\r') ? eol - 1 : eol;
    ParseLine(p, line_end);
    p = eol + 1;
  }
  return std::move(samples_);
}

void RecordingParser::ParseLine(const char* begin, const char* end) {
  const char* p = begin;
  while (p < end && detail::IsBlank(*p)) ++p;
  if (p == end || *p == '#') return;

  std::array<double, kMaxFields> values{};
  const char* t_begin = p;
  int count = 0;
  while (p < end) {
    if (count == kMaxFields) {
      Fail(begin, end, p, fmt::format("too many fields: expected t ax ay az [temp_c]"));
    }
    p = ParseField(p, begin, end, count, &values[static_cast<size_t>(count)]);
    ++count;
    p = SkipSeparator(p, begin, end);
  }
  CheckFieldCount(count, begin, end);
  CheckTime(values[0], t_begin, begin, end);

  Sample& sample = samples_.emplace_back();
  sample.t_s = values[0];
  sample.raw_counts = {values[1], values[2], values[3]};
  if (count == kMaxFields) sample.temp_c = values[4];
  if (fields_per_line_ == 0) {
    fields_per_line_ = count;
    first_data_line_ = line_number_;
  }
  previous_t_line_ = line_number_;
}

const char* RecordingParser::ParseField(const char* p, const char* line_begin, const char* end,
                                        int index, double* value) const {
  const char* start = p;
  if (p < end && *p == '+' && p + 1 < end && p[1] != '-' && p[1] != '+') ++p;
  const auto [next, ec] = std::from_chars(p, end, *value);
  if (ec != std::errc() || (next < end && !IsSeparatorChar(*next))) {
    const char* token_end = start;
    while (token_end < end && !IsSeparatorChar(*token_end)) ++token_end;
    Fail(line_begin, end, start,
         fmt::format("field '{}': '{}' is not a number", kFieldNames[static_cast<size_t>(index)],
                     std::string_view(start, static_cast<size_t>(token_end - start))));
  }
  if (!std::isfinite(*value)) {
    Fail(line_begin, end, start,
         fmt::format("field '{}': '{}' is not a finite number",
                     kFieldNames[static_cast<size_t>(index)],
                     std::string_view(start, static_cast<size_t>(next - start))));
  }
  return next;
}

const char* RecordingParser::SkipSeparator(const char* p, const char* line_begin,
                                           const char* end) const {
  while (p < end && detail::IsBlank(*p)) ++p;
  if (p == end || *p != ',') return p;
  const char* comma = p++;
  while (p < end && detail::IsBlank(*p)) ++p;
  if (p == end || *p == ',') {
    Fail(line_begin, end, p == end ? comma : p, "empty field (two commas, or a trailing comma)");
  }
  return p;
}

void RecordingParser::CheckFieldCount(int count, const char* line_begin, const char* end) const {
  if (count < kMinFields) {
    Fail(line_begin, end, end,
         fmt::format("{} field{} here, expected t ax ay az [temp_c]", count,
                     count == 1 ? "" : "s"));
  }
  if (fields_per_line_ != 0 && count != fields_per_line_) {
    Fail(line_begin, end, end,
         fmt::format("{} fields here but {} on line {}, the first data line", count,
                     fields_per_line_, first_data_line_));
  }
}

void RecordingParser::CheckTime(double t_s, const char* t_begin, const char* line_begin,
                                const char* end) const {
  if (samples_.empty()) return;
  const double previous = samples_.back().t_s;
  if (!(t_s > previous)) {
    Fail(line_begin, end, t_begin,
         fmt::format("t = {} s does not increase (line {} has t = {} s); t must be strictly "
                     "increasing", detail::FormatNumber(t_s), previous_t_line_,
                     detail::FormatNumber(previous)));
  }
}

}  // namespace

std::vector<Sample> ReadRecordingFile(const std::string& path) {
  return ParseRecording(detail::ReadWholeFile(path), path);
}

std::vector<Sample> ParseRecording(std::string_view text, const std::string& source_name) {
  return RecordingParser(text, source_name).Run();
}

}  // namespace accelcal
