#include "accelcal/base/sample_line_parser.h"

#include <array>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "accelcal/base/text_scan.h"
#include "accelcal/base/error.h"

namespace accelcal::detail {
namespace {

constexpr int kMinFields = 4;
constexpr int kMaxFields = 5;
constexpr std::array<std::string_view, kMaxFields> kFieldNames = {"t", "ax", "ay", "az",
                                                                   "temp_c"};

inline bool IsSeparatorChar(char c) { return c == ' ' || c == '\t' || c == ','; }

}  // namespace

bool SampleLineParser::Parse(std::string_view line, long line_number, Sample* sample) {
  line_number_ = line_number;
  const char* const begin = line.data();
  const char* const end = begin + line.size();
  const char* p = begin;
  while (p < end && IsBlank(*p)) ++p;
  if (p == end || *p == '#') return false;

  std::array<double, kMaxFields> values{};
  const char* t_begin = p;
  int count = 0;
  while (p < end) {
    if (count == kMaxFields) Fail(begin, end, p, "too many fields: expected t ax ay az [temp_c]");
    p = ParseField(p, begin, end, count, &values[static_cast<size_t>(count)]);
    ++count;
    p = SkipSeparator(p, begin, end);
  }
  CheckFieldCount(count, begin, end);
  CheckTime(values[0], t_begin, begin, end);

  sample->t_s = values[0];
  sample->raw_counts = {values[1], values[2], values[3]};
  sample->temp_c = count == kMaxFields ? values[4] : kNaN;
  if (fields_per_line_ == 0) {
    fields_per_line_ = count;
    first_data_line_ = line_number_;
  }
  has_previous_ = true;
  previous_t_s_ = values[0];
  previous_t_line_ = line_number_;
  return true;
}

const char* SampleLineParser::ParseField(const char* p, const char* begin, const char* end,
                                         int index, double* value) const {
  const char* start = p;
  // from_chars takes no leading '+'; accept one (but not "+-1" or "++1").
  if (p < end && *p == '+' && p + 1 < end && p[1] != '-' && p[1] != '+') ++p;
  const auto [next, ec] = std::from_chars(p, end, *value);
  if (ec != std::errc() || (next < end && !IsSeparatorChar(*next))) {
    const char* token_end = start;
    while (token_end < end && !IsSeparatorChar(*token_end)) ++token_end;
    Fail(begin, end, start,
         fmt::format("field '{}': '{}' is not a number", kFieldNames[static_cast<size_t>(index)],
                     std::string_view(start, static_cast<size_t>(token_end - start))));
  }
  if (!std::isfinite(*value)) {
    Fail(begin, end, start,
         fmt::format("field '{}': '{}' is not a finite number",
                     kFieldNames[static_cast<size_t>(index)],
                     std::string_view(start, static_cast<size_t>(next - start))));
  }
  return next;
}

const char* SampleLineParser::SkipSeparator(const char* p, const char* begin,
                                            const char* end) const {
  while (p < end && IsBlank(*p)) ++p;
  if (p == end || *p != ',') return p;
  const char* comma = p++;
  while (p < end && IsBlank(*p)) ++p;
  if (p == end || *p == ',')
    Fail(begin, end, p == end ? comma : p, "empty field (two commas, or a trailing comma)");
  return p;
}

void SampleLineParser::CheckFieldCount(int count, const char* begin, const char* end) const {
  if (count < kMinFields)
    Fail(begin, end, end,
         fmt::format("{} field{} here, expected t ax ay az [temp_c]", count, count == 1 ? "" : "s"));
  if (fields_per_line_ != 0 && count != fields_per_line_)
    Fail(begin, end, end,
         fmt::format("{} fields here but {} on line {}, the first data line", count,
                     fields_per_line_, first_data_line_));
}

void SampleLineParser::CheckTime(double t_s, const char* t_begin, const char* begin,
                                 const char* end) const {
  if (!has_previous_ || t_s > previous_t_s_) return;
  Fail(begin, end, t_begin,
       fmt::format("t = {} s does not increase (line {} has t = {} s); t must be strictly "
                   "increasing", FormatNumber(t_s), previous_t_line_, FormatNumber(previous_t_s_)));
}

void SampleLineParser::Fail(const char* begin, const char* end, const char* at,
                            const std::string& message) const {
  const std::string_view line(begin, static_cast<size_t>(end - begin));
  throw InputError(source_name_, line_number_, ColumnAt(line, static_cast<size_t>(at - begin)),
                   message);
}

}  // namespace accelcal::detail
