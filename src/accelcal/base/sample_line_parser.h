// One data line of a sample table into a Sample, by a column layout: the protocol's positional
// `t ax ay az [temp_c]` (every data line with the field count of the first one), or the columns
// a header row or `--columns` named (every data line with exactly that many fields).
//
// Separators (SetDelimiter): by default blanks (spaces, tabs) and/or one comma or one semicolon
// between fields; a file whose header is split by commas, semicolons or tabs uses that delimiter
// alone (blanks around a field are trimmed, two delimiters in a row are an empty field). With
// semicolons, a comma inside a number is its decimal mark ("9,81").
//
// Values: every named column a finite number (from_chars; a leading '+' accepted); temp_c may be
// empty (unknown: NaN) when the columns are named; ignored columns ("-") are not read. t is
// scaled by its unit (t_ms ...), ax ay az multiplied by the reading scale (sample_format.h).
// The order of t is not judged here (sample_time_check.h does).
//
// Errors: InputError naming the line and the 1-based column of the offending field, e.g.
// "field 'ay': '2x' is not a number"; the token is quoted at most 40 characters long, anything
// unprintable shown as '?'. A failed line leaves the parser's state as it was. Internal to src/.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/line_shapes.h"
#include "accelcal/base/sample_columns.h"

namespace accelcal::detail {

class SampleLineParser {
 public:
  static constexpr int kMaxColumns = 64;
  // Fields of a positional line: t ax ay az, and temp_c or not.
  static constexpr int kMinPositional = 4;
  static constexpr int kMaxPositional = 5;

  explicit SampleLineParser(std::string source_name) : source_name_(std::move(source_name)) {}

  // Named columns instead of the positional protocol; `columns` passes CheckColumnLayout and has
  // at most kMaxColumns entries. `names` (same size, may be empty) are the header's own names,
  // for messages.
  void UseColumns(const std::vector<NamedColumn>& columns, const std::vector<std::string>& names);
  // 0: blanks and/or one comma or semicolon; ',' ';' or '\t': that delimiter alone.
  void SetDelimiter(char delimiter) { delimiter_ = delimiter; }
  // ax, ay, az are multiplied by this (1: counts as they are).
  void SetReadingScale(double scale) { reading_scale_ = scale; }
  // False: every line through the general path, never the one-pass path of plain lines (the
  // tests hold the two to the same samples and the same errors).
  void SetPlainFastPath(bool enabled) { plain_fast_path_ = enabled; }

  // Parses `line` (no terminator; not blank, not a comment), the `line_number`-th (1-based) of
  // the source. Fills *sample (t NaN without a t column) and returns the byte offset of the t
  // field in `line` (0 without one). Throws InputError.
  size_t Parse(std::string_view line, long line_number, Sample* sample);

  // The lane of a long file of plain lines (SampleReader's): true once the first data line has
  // set the positional field count, with blanks and/or commas between fields.
  bool TakesPaddedLines() const {
    return plain_fast_path_ && positional_ && delimiter_ == 0 && fields_per_line_ != 0;
  }
  // With TakesPaddedLines(): the line at `line`, when it is the common plain line (no leading
  // blank, fields_per_line() numbers in decimal_scan.h's short form, separated as Parse
  // separates them, ended by LF or CR LF, at most kPaddedLineBytes before its LF), read into
  // *sample as Parse reads it: by its shape when an earlier line had the same (line_shapes.h),
  // else number after number. Returns its LF, or nullptr for any other line (Parse then reads
  // it, and words what is wrong). Reads up to kPaddedLineReach bytes from `line`, whatever the
  // line's length: the caller's buffer must hold them.
  static constexpr long kPaddedLineBytes = 112;
  static constexpr long kPaddedLineReach = kPaddedLineBytes + 24;
  const char* ParsePaddedLine(const char* line, Sample* sample) {
    std::array<double, kMaxPositional> values;
    const char* const lf = shapes_.Read(line, fields_per_line_, values.data());
    if (lf == nullptr) return ParsePaddedLineByNumbers(line, sample);
    FillPositional(values, sample);
    return lf;
  }

  bool has_t_column() const { return t_slot_ >= 0 || positional_; }
  bool positional() const { return positional_; }
  // Positional: the field count of the first data line (0 before it).
  int fields_per_line() const { return fields_per_line_; }
  const std::string& source_name() const { return source_name_; }

  // The InputError of a message about `line` at byte `offset` (for checks made by the caller).
  [[noreturn]] void Fail(std::string_view line, long line_number, size_t offset,
                         const std::string& message) const;

 private:
  enum Slot : std::int8_t { kSlotT = 0, kSlotAx, kSlotAy, kSlotAz, kSlotTemp, kSlotIgnore };

  bool ParsePlainPositional(std::string_view line, Sample* sample, size_t* t_offset) const;
  const char* ParsePaddedLineByNumbers(const char* line, Sample* sample);
  // A plain positional line's numbers (fields_per_line() of them) into *sample.
  void FillPositional(const std::array<double, kMaxPositional>& values, Sample* sample) const {
    sample->t_s = values[kSlotT];
    sample->raw_counts = {values[kSlotAx], values[kSlotAy], values[kSlotAz]};
    if (reading_scale_ != 1.0) sample->raw_counts *= reading_scale_;
    sample->temp_c = fields_per_line_ == kMaxPositional ? values[kSlotTemp] : kNaN;
  }
  bool IsSeparator(char c) const;
  const char* TokenEnd(const char* p, const char* end) const;
  void ReadNumber(const char* start, const char* token_end, int field, double* value) const;
  std::string FieldName(int field) const;
  std::string Expected() const;
  [[noreturn]] void FailAt(const char* at, const std::string& message) const;

  std::string source_name_;
  bool positional_ = true;
  std::array<Slot, kMaxColumns> slots_{};
  int num_columns_ = 0;        // named columns: fields per line
  int t_slot_ = -1;            // field index of t (named columns), -1 without
  double time_to_s_ = 1.0;
  std::vector<std::string> names_;  // header names (for messages), may be empty
  char delimiter_ = 0;
  double reading_scale_ = 1.0;
  bool plain_fast_path_ = true;
  LineShapes shapes_;          // of the padded lines read so far
  int fields_per_line_ = 0;    // positional: set by the first data line
  long first_data_line_ = 0;
  // The line being parsed (for messages).
  std::string_view line_;
  long line_number_ = 0;
};

// Splits a header row into its cells by `delimiter` (as SetDelimiter), one pair of surrounding
// double quotes removed from each cell, blanks trimmed.
std::vector<std::string> SplitHeaderCells(std::string_view line, char delimiter);

// The delimiter a header row (or, without one, the first data line) implies: ';' when it holds a
// semicolon; for a header, ',' or '\t' when it holds one; else 0 (blanks and/or commas).
char DetectDelimiter(std::string_view line, bool is_header);

// True when `line` (not blank, not a comment) looks like a header rather than data: one of its
// blank-, comma- or semicolon-separated tokens starts with a letter, '_' or '"' and is not a
// number word (nan, inf, infinity).
bool LooksLikeHeader(std::string_view line);

}  // namespace accelcal::detail
