#include "accelcal/base/sample_line_parser.h"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "accelcal/base/decimal_scan.h"
#include "accelcal/base/error.h"
#include "accelcal/base/text_scan.h"

namespace accelcal::detail {
namespace {

constexpr std::array<std::string_view, SampleLineParser::kMaxPositional> kPositionalNames = {
    "t", "ax", "ay", "az", "temp_c"};
constexpr size_t kMaxQuoted = 40;  // characters of a bad token quoted in a message

// Parse's separator after a number: blanks, then at most one comma or semicolon with blanks
// after it. Returns where that run ends (p itself when there is none), and in *delimited
// whether it held the comma or semicolon.
const char* SeparatorRunEnd(const char* p, const char* end, bool* delimited) {
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
  *delimited = p < end && (*p == ',' || *p == ';');
  if (*delimited) {
    ++p;
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
  }
  return p;
}

bool IsNumberWord(std::string_view token) {
  std::string lower;
  for (char c : token) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  if (!lower.empty() && (lower.front() == '+' || lower.front() == '-')) lower.erase(0, 1);
  return lower == "nan" || lower == "inf" || lower == "infinity";
}

}  // namespace

void SampleLineParser::UseColumns(const std::vector<NamedColumn>& columns,
                                  const std::vector<std::string>& names) {
  positional_ = false;
  num_columns_ = static_cast<int>(std::min<size_t>(columns.size(), kMaxColumns));
  names_ = names;
  t_slot_ = -1;
  for (int i = 0; i < num_columns_; ++i) {
    const NamedColumn& c = columns[static_cast<size_t>(i)];
    switch (c.column) {
      case SampleColumn::kT:
        slots_[static_cast<size_t>(i)] = kSlotT;
        t_slot_ = i;
        time_to_s_ = c.time_to_s;
        break;
      case SampleColumn::kAx: slots_[static_cast<size_t>(i)] = kSlotAx; break;
      case SampleColumn::kAy: slots_[static_cast<size_t>(i)] = kSlotAy; break;
      case SampleColumn::kAz: slots_[static_cast<size_t>(i)] = kSlotAz; break;
      case SampleColumn::kTempC: slots_[static_cast<size_t>(i)] = kSlotTemp; break;
      case SampleColumn::kIgnore: slots_[static_cast<size_t>(i)] = kSlotIgnore; break;
    }
  }
}

bool SampleLineParser::IsSeparator(char c) const {
  if (delimiter_ != 0) return c == delimiter_;
  return c == ' ' || c == '\t' || c == ',' || c == ';';
}

// Blanks around a field: spaces, and tabs unless the tab is the delimiter.
static inline bool IsPad(char c, char delimiter) {
  return c == ' ' || (c == '\t' && delimiter != '\t');
}

const char* SampleLineParser::TokenEnd(const char* p, const char* end) const {
  while (p < end && !IsSeparator(*p)) ++p;
  return p;
}

std::string SampleLineParser::FieldName(int field) const {
  if (positional_) return std::string(kPositionalNames[static_cast<size_t>(field)]);
  const Slot slot = slots_[static_cast<size_t>(field)];
  const std::string canonical(
      slot == kSlotT ? "t" : slot == kSlotAx ? "ax" : slot == kSlotAy ? "ay"
      : slot == kSlotAz ? "az" : slot == kSlotTemp ? "temp_c" : "-");
  const size_t i = static_cast<size_t>(field);
  if (i < names_.size() && names_[i] != canonical)
    return fmt::format("{}' ('{}", canonical, PrintableExcerpt(names_[i], kMaxQuoted));
  return canonical;
}

std::string SampleLineParser::Expected() const {
  if (positional_) return "t ax ay az [temp_c]";
  std::string list;
  for (int i = 0; i < num_columns_; ++i) {
    const Slot s = slots_[static_cast<size_t>(i)];
    if (i > 0) list += ',';
    list += s == kSlotT ? "t" : s == kSlotAx ? "ax" : s == kSlotAy ? "ay" : s == kSlotAz ? "az"
            : s == kSlotTemp ? "temp_c" : "-";
  }
  return fmt::format("{} ({})", num_columns_, list);
}

void SampleLineParser::ReadNumber(const char* start, const char* token_end, int field,
                                  double* value) const {
  const char* p = start;
  // A semicolon file writes decimal commas ("9,81"): read them as points.
  char buffer[64];
  const char* last = token_end;
  if (delimiter_ == ';') {
    const size_t n = static_cast<size_t>(token_end - start);
    bool has_comma = false;
    for (const char* q = start; q < token_end; ++q) has_comma |= (*q == ',');
    if (has_comma && n < sizeof buffer) {
      for (size_t i = 0; i < n; ++i) buffer[i] = start[i] == ',' ? '.' : start[i];
      p = buffer;
      last = buffer + n;
    }
  }
  // from_chars takes no leading '+'; accept one (but not "+-1" or "++1").
  if (p < last && *p == '+' && p + 1 < last && p[1] != '-' && p[1] != '+') ++p;
  if (ScanSimpleDecimal(p, last, value)) return;  // the same double, faster (decimal_scan.h)
  const auto [next, ec] = std::from_chars(p, last, *value);
  const std::string_view token(start, static_cast<size_t>(token_end - start));
  if (ec != std::errc() || next != last) {
    FailAt(start, fmt::format("field '{}': '{}' is not a number", FieldName(field),
                              PrintableExcerpt(token, kMaxQuoted)));
  }
  if (!std::isfinite(*value)) {
    FailAt(start, fmt::format("field '{}': '{}' is not a finite number", FieldName(field),
                              PrintableExcerpt(token, kMaxQuoted)));
  }
}

// The common line of a logger's file, in one pass: the positional layout split by blanks and/or
// one comma or semicolon, every field a plain decimal (decimal_scan.h), as many fields as the
// first data line. False, with *sample untouched, for anything else: Parse's general path then
// reads the line, so values and messages are those of the general path. A number's end needs no
// separate token scan: a number ends at a separator or the end of the line, or the line is not
// plain.
bool SampleLineParser::ParsePlainPositional(std::string_view line, Sample* sample,
                                            size_t* t_offset) const {
  const char* const begin = line.data();
  const char* const end = begin + line.size();
  const char* p = begin;
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
  const char* const t_begin = p;
  std::array<double, kMaxPositional> values;
  int count = 0;
  while (p < end) {
    if (count == kMaxPositional) return false;
    p = ScanDecimalPrefix(p, end, &values[static_cast<size_t>(count)]);
    if (p == nullptr) return false;
    ++count;
    // A separator, then a field or the end.
    const char* const field_end = p;
    bool delimited = false;
    p = SeparatorRunEnd(p, end, &delimited);
    if (delimited && p == end) return false;  // a trailing comma: the general path words it
    if (!delimited && p == field_end && p < end)
      return false;  // the number runs into something that is not a separator
  }
  if (count != fields_per_line_) return false;
  FillPositional(values, sample);
  *t_offset = static_cast<size_t>(t_begin - begin);
  return true;
}

namespace {

// Where the next field of a padded line starts after a number that is not the last (Parse's
// separator, at least one character of it), or nullptr without one or at `limit`. The common
// case first: one blank or comma, then the next number's first character.
inline const char* NextField(const char* p, const char* limit) {
  const char c = p[1];
  if ((*p == ' ' || *p == ',') && (static_cast<unsigned>(c - '0') < 10u || c == '-') &&
      p < limit)
    return p + 1;
  bool delimited = false;
  const char* const next = SeparatorRunEnd(p, limit, &delimited);
  return next == p || next >= limit ? nullptr : next;
}

// kFields numbers of a padded line into values; returns the character after the last one.
template <int kFields>
const char* ScanPaddedFields(const char* p, const char* limit, double* values) {
  for (int field = 0; field < kFields; ++field) {
    if (field > 0) {
      p = NextField(p, limit);
      if (p == nullptr) return nullptr;
    }
    p = ScanShortDecimal(p, &values[field]);
    if (p == nullptr) return nullptr;
  }
  return p;
}

}  // namespace

const char* SampleLineParser::ParsePaddedLineByNumbers(const char* line, Sample* sample) {
  static_assert(LineShapes::kReach <= kPaddedLineReach && LineShapes::kMaxFields >= kMaxPositional);
  // Every field starts before `limit`, so a number's reach stays within kPaddedLineReach.
  const char* const limit = line + kPaddedLineBytes;
  std::array<double, kMaxPositional> values;
  const char* p = fields_per_line_ == kMaxPositional
                      ? ScanPaddedFields<kMaxPositional>(line, limit, values.data())
                      : ScanPaddedFields<kMinPositional>(line, limit, values.data());
  if (p == nullptr) return nullptr;
  if (*p == '\r') ++p;
  if (*p != '\n') return nullptr;
  shapes_.Learn(line, p, fields_per_line_);
  FillPositional(values, sample);
  return p;
}

size_t SampleLineParser::Parse(std::string_view line, long line_number, Sample* sample) {
  // Positional, blank/comma-separated, after the first line set the field count (the first
  // line's errors and count come from the general path).
  if (plain_fast_path_ && positional_ && delimiter_ == 0 && fields_per_line_ != 0) {
    size_t t_offset = 0;
    if (ParsePlainPositional(line, sample, &t_offset)) return t_offset;
  }
  line_ = line;
  line_number_ = line_number;
  const char* const begin = line.data();
  const char* const end = begin + line.size();
  const char d = delimiter_;
  const char* p = begin;
  while (p < end && IsPad(*p, d)) ++p;

  std::array<double, 6> values{0.0, 0.0, 0.0, 0.0, kNaN, 0.0};
  const int max_fields = positional_ ? kMaxPositional : num_columns_;
  const char* t_begin = begin;
  int count = 0;
  for (;;) {
    const char* token_end = TokenEnd(p, end);
    const char* trimmed_end = token_end;
    while (trimmed_end > p && IsPad(trimmed_end[-1], d)) --trimmed_end;
    if (count == max_fields) FailAt(p, fmt::format("too many fields: expected {}", Expected()));
    const Slot slot = positional_ ? static_cast<Slot>(count) : slots_[static_cast<size_t>(count)];
    if (trimmed_end == p) {
      // Only a delimiter file has empty fields here: a blank-separated one never yields one.
      if (positional_ || (slot != kSlotIgnore && slot != kSlotTemp))
        FailAt(p, d == ';' ? "empty field (two semicolons, or a trailing semicolon)"
                 : d == '\t' ? "empty field (two tabs, or a trailing tab)"
                             : "empty field (two commas, or a trailing comma)");
    } else if (slot != kSlotIgnore) {
      if (slot == kSlotT) t_begin = p;
      ReadNumber(p, trimmed_end, count, &values[static_cast<size_t>(slot)]);
    }
    ++count;
    p = token_end;
    if (d != 0) {
      if (p == end) break;
      ++p;  // the delimiter
      while (p < end && IsPad(*p, d)) ++p;
      continue;
    }
    while (p < end && IsPad(*p, d)) ++p;
    if (p == end) break;
    if (*p == ',' || *p == ';') {
      const char* separator = p++;
      while (p < end && IsPad(*p, d)) ++p;
      if (p == end || *p == ',' || *p == ';')
        FailAt(p == end ? separator : p, "empty field (two commas, or a trailing comma)");
    }
  }

  if (positional_) {
    if (count < kMinPositional)
      FailAt(end, fmt::format("{} field{} here, expected t ax ay az [temp_c]", count,
                              count == 1 ? "" : "s"));
    if (fields_per_line_ != 0 && count != fields_per_line_)
      FailAt(end, fmt::format("{} fields here but {} on line {}, the first data line", count,
                              fields_per_line_, first_data_line_));
    if (fields_per_line_ == 0) {
      fields_per_line_ = count;
      first_data_line_ = line_number;
    }
    if (count < kMaxPositional) values[kSlotTemp] = kNaN;
  } else if (count < num_columns_) {
    FailAt(end, fmt::format("{} field{} here, expected {}", count, count == 1 ? "" : "s",
                            Expected()));
  }

  const bool has_t = positional_ || t_slot_ >= 0;
  sample->t_s = has_t ? values[kSlotT] * time_to_s_ : kNaN;
  sample->raw_counts = {values[kSlotAx], values[kSlotAy], values[kSlotAz]};
  if (reading_scale_ != 1.0) sample->raw_counts *= reading_scale_;
  sample->temp_c = values[kSlotTemp];
  return has_t ? static_cast<size_t>(t_begin - begin) : 0;
}

void SampleLineParser::FailAt(const char* at, const std::string& message) const {
  Fail(line_, line_number_, static_cast<size_t>(at - line_.data()), message);
}

void SampleLineParser::Fail(std::string_view line, long line_number, size_t offset,
                            const std::string& message) const {
  throw InputError(source_name_, line_number, ColumnAt(line, offset), message);
}

std::vector<std::string> SplitHeaderCells(std::string_view line, char delimiter) {
  std::vector<std::string> cells;
  const auto push = [&](std::string_view cell) {
    cell = TrimBlanks(cell);
    if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"')
      cell = cell.substr(1, cell.size() - 2);
    cells.emplace_back(TrimBlanks(cell));
  };
  if (delimiter != 0) {
    size_t start = 0;
    for (;;) {
      const size_t at = line.find(delimiter, start);
      push(line.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start));
      if (at == std::string_view::npos) break;
      start = at + 1;
    }
    return cells;
  }
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (IsBlank(line[i]) || line[i] == ',' || line[i] == ';')) ++i;
    const size_t start = i;
    while (i < line.size() && !IsBlank(line[i]) && line[i] != ',' && line[i] != ';') ++i;
    if (i > start) push(line.substr(start, i - start));
  }
  return cells;
}

char DetectDelimiter(std::string_view line, bool is_header) {
  if (line.find(';') != std::string_view::npos) return ';';
  if (!is_header) return 0;
  if (line.find(',') != std::string_view::npos) return ',';
  if (line.find('\t') != std::string_view::npos) return '\t';
  return 0;
}

bool LooksLikeHeader(std::string_view line) {
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (IsBlank(line[i]) || line[i] == ',' || line[i] == ';')) ++i;
    const size_t start = i;
    while (i < line.size() && !IsBlank(line[i]) && line[i] != ',' && line[i] != ';') ++i;
    if (i == start) continue;
    const std::string_view token = line.substr(start, i - start);
    const char c = token.front();
    const bool wordish = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '"';
    if (wordish && !IsNumberWord(token)) return true;
  }
  return false;
}

}  // namespace accelcal::detail
