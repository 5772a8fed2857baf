#include "accelcal/io/capture_set_reader.h"

#include <array>
#include <climits>
#include <cmath>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "accelcal/io/csv_fields.h"
#include "accelcal/io/detail/read_file.h"
#include "accelcal/base/sample_columns.h"
#include "accelcal/base/text_scan.h"
#include "accelcal/base/error.h"

namespace accelcal {
namespace {


enum Column : int {
  kCapture, kKind, kT, kAx, kAy, kAz, kTempC, kRadiusM, kRpm, kLabel, kUpAxis, kUp, kNumColumns
};
constexpr std::array<std::string_view, kNumColumns> kColumnNames = {
    "capture", "kind", "t", "ax", "ay", "az", "temp_c", "radius_m", "rpm", "label", "up_axis", "up"};
constexpr int kNumRequiredColumns = kTempC;  // the columns before temp_c are required

constexpr std::string_view kAdcRangeKey = "adc_range_counts";

// The column a header cell names: its exact name, or for the sample columns a common spelling
// (base/sample_columns.h; a time column in seconds only); kNumColumns when none.
int ColumnOfName(std::string_view name) {
  for (int c = 0; c < kNumColumns; ++c)
    if (kColumnNames[static_cast<size_t>(c)] == name) return c;
  const NamedColumn named = RecognizeColumnName(name);
  switch (named.column) {
    case SampleColumn::kT: return named.time_to_s == 1.0 ? kT : kNumColumns;
    case SampleColumn::kAx: return kAx;
    case SampleColumn::kAy: return kAy;
    case SampleColumn::kAz: return kAz;
    case SampleColumn::kTempC: return kTempC;
    case SampleColumn::kIgnore: return kNumColumns;
  }
  return kNumColumns;
}

// One data row, parsed.
struct Row {
  long id = 0;
  CaptureKind kind = CaptureKind::kStatic;
  Sample sample;
  double radius_m = kNaN;
  double rpm = kNaN;
  std::string label;
  std::optional<SensorAxis> up_axis;
  std::optional<Eigen::Vector3d> up;
};

// Line span of a capture already read, to report a non-contiguous id.
struct LineSpan {
  long first = 0;
  long last = 0;
};

class CaptureSetParser {
 public:
  CaptureSetParser(std::string_view text, const std::string& source_name)
      : lines_(detail::StripBom(text)) {
    set_.source_name = source_name;
  }

  CaptureSet Run();

 private:
  [[noreturn]] void FailAt(size_t offset, const std::string& message) const {
    throw InputError(set_.source_name, lines_.line_number(), detail::ColumnAt(line_, offset),
                     message);
  }
  [[noreturn]] void FailAtField(Column c, const std::string& message) const {
    FailAt(Field(c)->offset, message);
  }

  void ParseComment(size_t hash_offset);
  void ParseHeader();
  void ParseDataLine();
  Row ParseRow() const;
  void ParseTurntableColumns(Row* row) const;
  void CheckStaticColumnEmpty(Column c) const;
  void CheckTurntableColumnEmpty(Column c) const;
  void ParseUp(Row* row) const;
  void AddRow(Row row);
  void StartCapture(Row row);
  void CheckSameAsFirstRow(const Row& row) const;

  // The row's field for column c; nullptr when the header has no such column.
  const CsvField* Field(Column c) const {
    return column_index_[c] < 0 ? nullptr : &fields_[static_cast<size_t>(column_index_[c])];
  }
  double Number(Column c) const;
  double FiniteNumber(Column c) const;
  double PositiveNumber(Column c) const;

  detail::LineReader lines_;
  std::string_view line_;          // the line being parsed
  std::vector<CsvField> fields_;   // its fields
  CaptureSet set_;
  long adc_range_line_ = 0;
  long header_line_ = 0;
  std::array<int, kNumColumns> column_index_{};  // field index of each column, -1 if absent
  size_t num_header_fields_ = 0;
  // The capture being filled: its first row and that row's line.
  Row first_row_;
  long first_row_line_ = 0;
  std::map<long, LineSpan> finished_;  // captures already closed, by id
  double previous_t_s_ = -INFINITY;
  long previous_row_line_ = 0;  // line of the last data row added
};

CaptureSet CaptureSetParser::Run() {
  while (lines_.Next(&line_)) {
    const std::string_view trimmed = detail::TrimBlanks(line_);
    if (trimmed.empty()) continue;
    if (trimmed.front() == '#') {
      ParseComment(static_cast<size_t>(trimmed.data() - line_.data()));
    } else if (header_line_ == 0) {
      ParseHeader();
    } else {
      ParseDataLine();
    }
  }
  if (header_line_ == 0) {
    throw InputError(set_.source_name, 0, 0,
                     "no header row: the file is empty or holds only comments");
  }
  if (set_.captures.empty()) {
    throw InputError(set_.source_name, header_line_, 0, "a header but no data rows");
  }
  return std::move(set_);
}

void CaptureSetParser::ParseComment(size_t hash_offset) {
  const std::string_view body = line_.substr(hash_offset + 1);
  const std::string_view trimmed = detail::TrimBlanks(body);
  if (trimmed.substr(0, kAdcRangeKey.size()) != kAdcRangeKey) return;
  std::string_view rest = trimmed.substr(kAdcRangeKey.size());
  // "adc_range_counts_v2" or "adc_range_counts: note" are ordinary comments.
  if (!rest.empty() && !detail::IsBlank(rest.front()) && rest.front() != '=') return;
  const size_t key_offset = static_cast<size_t>(trimmed.data() - line_.data());
  const std::string usage = "expected '# adc_range_counts = MIN,MAX' (counts, MIN < MAX)";
  if (adc_range_line_ != 0) {
    FailAt(key_offset, fmt::format("adc_range_counts given twice (first on line {})",
                                   adc_range_line_));
  }
  rest = detail::TrimBlanks(rest);
  if (rest.empty() || rest.front() != '=') FailAt(key_offset, usage);
  rest = detail::TrimBlanks(rest.substr(1));
  const size_t value_offset = static_cast<size_t>(rest.data() - line_.data());
  const size_t comma = rest.find(',');
  AdcRange range;
  if (comma == std::string_view::npos ||
      !detail::ParseDouble(detail::TrimBlanks(rest.substr(0, comma)), &range.min_counts) ||
      !detail::ParseDouble(detail::TrimBlanks(rest.substr(comma + 1)), &range.max_counts) ||
      !std::isfinite(range.min_counts) || !std::isfinite(range.max_counts) ||
      !(range.min_counts < range.max_counts)) {
    FailAt(value_offset, fmt::format("'{}': {}", rest, usage));
  }
  set_.adc_range = range;
  adc_range_line_ = lines_.line_number();
}

void CaptureSetParser::ParseHeader() {
  const CsvSplitError split = SplitCsvLine(line_, &fields_);
  if (!split.message.empty()) FailAt(split.offset, split.message);
  column_index_.fill(-1);
  for (size_t i = 0; i < fields_.size(); ++i) {
    const std::string& name = fields_[i].value;
    const int c = ColumnOfName(name);
    if (c == kNumColumns) {
      FailAt(fields_[i].offset,
             fmt::format("unknown column '{}' in the header (known: capture, kind, t, ax, ay, "
                         "az, temp_c, radius_m, rpm, label, up_axis, up; t, ax, ay, az and "
                         "temp_c also in their common spellings: time, acc_x, AccX, ...)",
                         detail::PrintableExcerpt(name, 40)));
    }
    if (column_index_[c] >= 0) {
      const std::string& first = fields_[static_cast<size_t>(column_index_[c])].value;
      FailAt(fields_[i].offset,
             first == name ? fmt::format("column '{}' appears twice in the header", name)
                           : fmt::format("column '{}' appears twice in the header (as '{}' and "
                                         "'{}')", kColumnNames[c], first, name));
    }
    column_index_[c] = static_cast<int>(i);
  }
  for (int c = 0; c < kNumRequiredColumns; ++c) {
    if (column_index_[c] < 0) {
      FailAt(0, fmt::format("the header lacks the required column '{}' (required: capture, "
                            "kind, t, ax, ay, az)", kColumnNames[c]));
    }
  }
  num_header_fields_ = fields_.size();
  header_line_ = lines_.line_number();
}

void CaptureSetParser::ParseDataLine() {
  const CsvSplitError split = SplitCsvLine(line_, &fields_);
  if (!split.message.empty()) FailAt(split.offset, split.message);
  if (fields_.size() != num_header_fields_) {
    const std::string message =
        fmt::format("wrong number of fields: {} here, {} in the header (line {})",
                    fields_.size(), num_header_fields_, header_line_);
    // Point at the first extra field, or at the end of the line where fields are missing.
    FailAt(fields_.size() > num_header_fields_ ? fields_[num_header_fields_].offset
                                               : line_.size(),
           message);
  }
  AddRow(ParseRow());
}

double CaptureSetParser::Number(Column c) const {
  const CsvField& field = *Field(c);
  double value = 0.0;
  if (!detail::ParseDouble(field.value, &value)) {
    FailAt(field.offset,
           fmt::format("column '{}': '{}' is not a number", kColumnNames[c], field.value));
  }
  return value;
}

double CaptureSetParser::FiniteNumber(Column c) const {
  const double value = Number(c);
  if (!std::isfinite(value)) {
    FailAtField(c, fmt::format("column '{}': '{}' is not a finite number", kColumnNames[c],
                               Field(c)->value));
  }
  return value;
}

double CaptureSetParser::PositiveNumber(Column c) const {
  const double value = FiniteNumber(c);
  if (!(value > 0.0)) {
    FailAtField(c, fmt::format("column '{}': {} must be > 0", kColumnNames[c], Field(c)->value));
  }
  return value;
}

Row CaptureSetParser::ParseRow() const {
  Row row;
  const CsvField& id = *Field(kCapture);
  if (!detail::ParseLong(id.value, &row.id) || row.id < 0 || row.id > INT_MAX) {
    FailAt(id.offset, fmt::format("column 'capture': '{}' is not a capture id (an integer "
                                  "from 0 to {})", id.value, INT_MAX));
  }
  const CsvField& kind = *Field(kKind);
  const std::optional<CaptureKind> parsed_kind = StringToCaptureKind(kind.value);
  if (!parsed_kind) {
    FailAt(kind.offset, fmt::format("column 'kind': unknown kind '{}' (expected 'static' or "
                                    "'turntable')", kind.value));
  }
  row.kind = *parsed_kind;
  row.sample.t_s = FiniteNumber(kT);
  // Non-finite readings are data, not syntax: screening rejects the capture with a reason.
  row.sample.raw_counts = {Number(kAx), Number(kAy), Number(kAz)};
  if (const CsvField* temp = Field(kTempC); temp != nullptr && !temp->value.empty()) {
    row.sample.temp_c = Number(kTempC);
    if (std::isinf(row.sample.temp_c)) {  // "nan" means unknown, like an empty field
      FailAt(temp->offset, fmt::format("column 'temp_c': '{}' is not a finite number",
                                       temp->value));
    }
  }
  if (row.kind == CaptureKind::kTurntable) {
    ParseTurntableColumns(&row);
  } else {
    CheckStaticColumnEmpty(kRadiusM);
    CheckStaticColumnEmpty(kRpm);
    CheckStaticColumnEmpty(kUpAxis);
    ParseUp(&row);
  }
  if (row.kind == CaptureKind::kTurntable) CheckTurntableColumnEmpty(kUp);
  if (const CsvField* label = Field(kLabel)) row.label = label->value;
  return row;
}

void CaptureSetParser::ParseTurntableColumns(Row* row) const {
  for (const Column c : {kRadiusM, kRpm}) {
    const CsvField* field = Field(c);
    if (field == nullptr) {
      FailAtField(kKind, fmt::format("a turntable row needs {0}, but the header has no '{0}' "
                                     "column", kColumnNames[c]));
    }
    if (field->value.empty()) {
      FailAt(field->offset,
             fmt::format("column '{}': a turntable row needs a value (> 0)", kColumnNames[c]));
    }
  }
  row->radius_m = PositiveNumber(kRadiusM);
  row->rpm = PositiveNumber(kRpm);
  if (const CsvField* up = Field(kUpAxis); up != nullptr && !up->value.empty()) {
    row->up_axis = StringToSensorAxis(up->value);
    if (!row->up_axis) {
      FailAt(up->offset, fmt::format("column 'up_axis': '{}' is not one of +x, -x, +y, -y, +z, -z",
                                     up->value));
    }
  }
}

void CaptureSetParser::CheckStaticColumnEmpty(Column c) const {
  const CsvField* field = Field(c);
  if (field != nullptr && !field->value.empty()) {
    FailAt(field->offset, fmt::format("column '{}': must be empty on a static row (got '{}')",
                                      kColumnNames[c], field->value));
  }
}

void CaptureSetParser::CheckTurntableColumnEmpty(Column c) const {
  const CsvField* field = Field(c);
  if (field != nullptr && !field->value.empty()) {
    FailAt(field->offset, fmt::format("column '{}': must be empty on a turntable row (its "
                                      "mounting is up_axis; got '{}')", kColumnNames[c],
                                      detail::PrintableExcerpt(field->value, 40)));
  }
}

// `up`: "+x" ... "-z", or three numbers separated by blanks ("0.577 0.577 -0.577"), normalized.
void CaptureSetParser::ParseUp(Row* row) const {
  const CsvField* field = Field(kUp);
  if (field == nullptr || field->value.empty()) return;
  if (const std::optional<SensorAxis> axis = StringToSensorAxis(field->value)) {
    row->up = SensorAxisVector(*axis);
    return;
  }
  Eigen::Vector3d v;
  std::string_view rest = field->value;
  int n = 0;
  bool ok = true;
  while (ok && !(rest = detail::TrimBlanks(rest)).empty()) {
    size_t end = 0;
    while (end < rest.size() && !detail::IsBlank(rest[end])) ++end;
    double x = 0.0;
    ok = n < 3 && detail::ParseDouble(rest.substr(0, end), &x) && std::isfinite(x);
    if (ok) v(n++) = x;
    rest.remove_prefix(end);
  }
  if (!ok || n != 3 || !(v.norm() > 0.0)) {
    FailAt(field->offset, fmt::format("column 'up': '{}' is not a direction (+x ... -z, or three "
                                      "numbers such as '0.577 0.577 -0.577')",
                                      detail::PrintableExcerpt(field->value, 40)));
  }
  row->up = v.normalized();
}

void CaptureSetParser::AddRow(Row row) {
  if (row.sample.t_s < previous_t_s_) {
    FailAtField(kT, fmt::format("column 't': t = {} s is earlier than t = {} s on line {} "
                                "(t must not decrease down the file)",
                                Field(kT)->value, detail::FormatNumber(previous_t_s_),
                                previous_row_line_));
  }
  previous_t_s_ = row.sample.t_s;
  const bool same_capture = !set_.captures.empty() && set_.captures.back().id == row.id;
  if (same_capture) {
    CheckSameAsFirstRow(row);
    set_.captures.back().samples.push_back(row.sample);
  } else {
    StartCapture(std::move(row));
  }
  previous_row_line_ = lines_.line_number();
}

void CaptureSetParser::StartCapture(Row row) {
  if (const auto seen = finished_.find(row.id); seen != finished_.end()) {
    FailAtField(kCapture,
                fmt::format("capture {} reappears after capture {} (which began on line {}); "
                            "it was on lines {}-{} and its rows must be contiguous",
                            row.id, set_.captures.back().id, first_row_line_, seen->second.first,
                            seen->second.last));
  }
  if (!set_.captures.empty()) {
    finished_[set_.captures.back().id] = {first_row_line_, previous_row_line_};
  }
  Capture& capture = set_.captures.emplace_back();
  capture.id = static_cast<int>(row.id);
  capture.kind = row.kind;
  capture.label = row.label;
  capture.radius_m = row.radius_m;
  capture.rpm = row.rpm;
  capture.up_axis = row.up_axis;
  capture.requested_up = row.up;
  capture.samples.push_back(row.sample);
  first_row_ = std::move(row);
  first_row_line_ = lines_.line_number();
}

void CaptureSetParser::CheckSameAsFirstRow(const Row& row) const {
  const auto differs = [&](Column c, const std::string& here, const std::string& first) {
    FailAtField(c, fmt::format("column '{}': '{}' differs from '{}' on line {}, the first row of "
                               "capture {} (kind, radius_m, rpm, label, up_axis and up must be "
                               "the same on all rows of a capture)",
                               kColumnNames[c], here, first, first_row_line_, row.id));
  };
  if (row.kind != first_row_.kind) {
    differs(kKind, std::string(CaptureKindToString(row.kind)),
            std::string(CaptureKindToString(first_row_.kind)));
  }
  // Static rows carry NaN in both; turntable rows were checked finite.
  if (row.kind == CaptureKind::kTurntable && row.radius_m != first_row_.radius_m) {
    differs(kRadiusM, Field(kRadiusM)->value, detail::FormatNumber(first_row_.radius_m));
  }
  if (row.kind == CaptureKind::kTurntable && row.rpm != first_row_.rpm) {
    differs(kRpm, Field(kRpm)->value, detail::FormatNumber(first_row_.rpm));
  }
  if (row.label != first_row_.label) differs(kLabel, row.label, first_row_.label);
  if (row.up != first_row_.up) {
    const auto text = [](const std::optional<Eigen::Vector3d>& u) {
      return u ? fmt::format("{:.4f} {:.4f} {:.4f}", u->x(), u->y(), u->z()) : std::string();
    };
    differs(kUp, text(row.up), text(first_row_.up));
  }
  if (row.up_axis != first_row_.up_axis) {
    const auto name = [](const std::optional<SensorAxis>& a) {
      return a ? std::string(SensorAxisToString(*a)) : std::string();
    };
    differs(kUpAxis, name(row.up_axis), name(first_row_.up_axis));
  }
}

}  // namespace

CaptureSet ReadCaptureSetFile(const std::string& path) {
  return ParseCaptureSet(detail::ReadWholeFile(path), path);
}

CaptureSet ParseCaptureSet(std::string_view text, const std::string& source_name) {
  return CaptureSetParser(text, source_name).Run();
}

}  // namespace accelcal
