#include "accelcal/base/sample_reader.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "accelcal/base/error.h"
#include "accelcal/base/text_scan.h"

namespace accelcal {
namespace {

constexpr size_t kMaxQuoted = 60;  // characters of a line quoted in a message
constexpr size_t kHintRows = 1000;  // rows whose magnitudes tell converted readings from counts

std::string JoinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string RateText(double interval_s) {
  if (!(interval_s > 0.0)) return "no interval yet";
  return fmt::format("median interval {:.6g} s ({:.6g} Hz)", interval_s, 1.0 / interval_s);
}

}  // namespace

std::string ReadingSummary::Describe() const {
  std::string out = fmt::format("{}: {} sample{}; ", source_name, samples, samples == 1 ? "" : "s");
  out += origin.empty() ? "columns " + columns : origin;
  if (!ignored.empty()) out += fmt::format(" (ignored: {})", JoinNames(ignored));
  if (skipped_rows > 0)
    out += fmt::format("; {} leading line{} skipped", skipped_rows, skipped_rows == 1 ? "" : "s");
  if (std::isfinite(rate_hz))
    out += fmt::format("; t = {} / {} Hz", origin.empty() ? "row" : "message", detail::FormatNumber(rate_hz));
  else
    out += fmt::format("; {}, {}", time_source.empty() ? "t from its column" : time_source,
                       RateText(median_interval_s));
  if (repaired_ties > 0)
    out += fmt::format("; {} repeated time stamp{} (printed to {} s) spread within their step",
                       repaired_ties, repaired_ties == 1 ? "" : "s",
                       fmt::format("{:.6g}", stamp_step_s));  // the step as printed, not its binary residue
  out += "; readings in " + unit.Describe();
  if (malformed > 0) out += fmt::format("; {} malformed line{} skipped", malformed, malformed == 1 ? "" : "s");
  for (const std::string& note : notes) out += "; " + note;
  return out;
}

SampleReader::SampleReader(std::string source_name, const SampleFormat& format,
                           OnMalformed on_malformed)
    : source_name_(std::move(source_name)),
      format_(format),
      on_malformed_(on_malformed),
      parser_(source_name_),
      time_check_(source_name_, format.repair_ties) {
  if (std::string e = format_.Validate(); !e.empty()) throw Error("sample format: " + e);
  time_from_rate_ = std::isfinite(format_.rate_hz);
  parser_.SetReadingScale(format_.unit.counts_per_unit);
  if (format_.HasExplicitLayout()) {
    parser_.UseColumns(format_.columns, {});
    std::string list;
    for (const NamedColumn& c : format_.columns) list += (list.empty() ? "" : ",") + ColumnListName(c);
    columns_text_ = list + " (as given)";
    if (!parser_.has_t_column() && !time_from_rate_)
      throw Error("the columns name no t: give the sample rate (--rate-hz)");
  } else {
    columns_text_ = "t ax ay az [temp_c] (the protocol's order)";
  }
}

size_t SampleReader::Consume(std::string_view text, bool final, std::vector<Sample>* out) {
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  const char* p = begin;
  const size_t cap = static_cast<size_t>(format_.max_line_bytes);
  while (p < end) {
    if (LaneOpen(p, end)) {
      p = TakePaddedLines(p, end, out);
      if (p == end) break;
    }
    if (skipping_) {
      const void* nl = std::memchr(p, '\n', static_cast<size_t>(end - p));
      if (nl == nullptr) return text.size();
      p = static_cast<const char*>(nl) + 1;
      skipping_ = false;
      continue;
    }
    const size_t remaining = static_cast<size_t>(end - p);
    // A line of `cap` bytes, a '\r' and the '\n': anything longer is not a text line.
    const size_t window = std::min(remaining, cap + 2);
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', window));
    if (eol == nullptr) {
      if (remaining >= cap + 2) {
        Overlong();  // kThrow throws
        skipping_ = true;
        continue;
      }
      if (!final) break;  // a partial line: wait for the rest
      eol = end;
    }
    std::string_view line(p, static_cast<size_t>(eol - p));
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    p = eol < end ? eol + 1 : end;
    if (line.size() > cap) {
      Overlong();
      continue;
    }
    ProcessLine(line, out);
  }
  return static_cast<size_t>(p - begin);
}

// The lane: the plain lines of a long file, read one after another straight from the buffer
// (the parser finds each line's end), each handled as ProcessLine and ParseData would handle it
// once the reading is settled: past the skipped rows and the header, the layout decided, the
// unit hint's rows seen, t from its column. Any other line, and the last kPaddedLineReach
// bytes of the text, go the way of every line.
bool SampleReader::LaneOpen(const char* p, const char* end) const {
  using Parser = detail::SampleLineParser;
  return end - p >= Parser::kPaddedLineReach && !skipping_ && layout_decided_ &&
         line_number_ >= std::max(lane_closed_until_line_, std::max(1L, format_.skip_rows)) &&
         parser_.TakesPaddedLines() && !time_from_rate_ &&
         first_magnitudes_.size() >= kHintRows &&
         (format_.require_temp_c.empty() ||
          parser_.fields_per_line() == Parser::kMaxPositional) &&
         format_.max_line_bytes >= Parser::kPaddedLineReach && time_errors_.empty();
}

const char* SampleReader::TakePaddedLines(const char* p, const char* end,
                                          std::vector<Sample>* out) {
  constexpr long kLinesClosed = 256;  // lines the lane stays closed after it took none
  const char* const last_start = end - detail::SampleLineParser::kPaddedLineReach;
  const char* const first = p;
  Sample s;
  while (p <= last_start) {
    const char* const eol = parser_.ParsePaddedLine(p, &s);
    if (eol == nullptr) break;
    std::string_view line(p, static_cast<size_t>(eol - p));
    if (line.back() == '\r') line.remove_suffix(1);
    ++line_number_;
    ++data_rows_;
    time_check_.Add(s, line, line_number_, 0, out, &time_errors_);
    p = eol + 1;
    if (!time_errors_.empty()) HandleTimeErrors();
  }
  if (p == first) lane_closed_until_line_ = line_number_ + kLinesClosed;
  return p;
}

void SampleReader::Feed(std::string_view bytes, std::vector<Sample>* out) {
  const size_t cap = static_cast<size_t>(format_.max_line_bytes);
  while (!bytes.empty()) {
    if (partial_.empty() || skipping_) {
      partial_.clear();
      const size_t used = Consume(bytes, false, out);
      bytes.remove_prefix(used);
      if (!skipping_) partial_.assign(bytes.data(), bytes.size());
      return;
    }
    // Complete the partial line with what comes up to its newline.
    const void* nl = std::memchr(bytes.data(), '\n', bytes.size());
    const size_t take = nl == nullptr ? bytes.size()
                                      : static_cast<size_t>(static_cast<const char*>(nl) - bytes.data()) + 1;
    if (partial_.size() + take > cap + 2) {
      // Too long either way (with or without its terminator): one malformed line.
      partial_.clear();
      Overlong();
      skipping_ = nl == nullptr;
      bytes.remove_prefix(take);
      continue;
    }
    partial_.append(bytes.data(), take);
    bytes.remove_prefix(take);
    if (nl != nullptr) {
      Consume(partial_, false, out);
      partial_.clear();
    }
  }
}

void SampleReader::Finish(std::vector<Sample>* out) {
  if (!skipping_ && !partial_.empty()) Consume(partial_, true, out);
  partial_.clear();
  skipping_ = false;
  time_check_.Finish(out, &time_errors_);
  HandleTimeErrors();
}

void SampleReader::DiscardPartial() {
  partial_.clear();
  skipping_ = false;
}

void SampleReader::ProcessLine(std::string_view line, std::vector<Sample>* out) {
  ++line_number_;
  if (line_number_ == 1) line = detail::StripBom(line);
  if (line_number_ <= format_.skip_rows) {
    ++skipped_rows_;
    return;
  }
  size_t first = 0;
  while (first < line.size() && detail::IsBlank(line[first])) ++first;
  if (first == line.size()) return;
  if (line[first] == '#') {
    if (comment_sink_) comment_sink_(line, data_rows_);
    return;
  }
  try {
    if (!layout_decided_ && TakeHeaderOrDecide(line)) return;
    ParseData(line, out);
  } catch (const InputError& e) {
    if (on_malformed_ == OnMalformed::kThrow) throw;
    Malformed(e);
  }
}

// The first line that is neither skipped, blank nor a comment: a header (consumed: true) or the
// first data line (the delimiter is taken from it once it parses).
bool SampleReader::TakeHeaderOrDecide(std::string_view line) {
  if (detail::LooksLikeHeader(line)) {
    UseHeader(line);
    layout_decided_ = true;
    return true;
  }
  parser_.SetDelimiter(detail::DetectDelimiter(line, false));
  return false;
}

void SampleReader::UseHeader(std::string_view line) {
  const char delimiter = detail::DetectDelimiter(line, true);
  const std::vector<std::string> cells = detail::SplitHeaderCells(line, delimiter);
  const std::string quoted = detail::PrintableExcerpt(line, kMaxQuoted);
  const auto fail = [&](const std::string& why) {
    throw InputError(source_name_, line_number_, 1, why);
  };
  if (format_.HasExplicitLayout()) {
    // The columns were given: the header only has to agree in number.
    if (cells.size() != format_.columns.size())
      fail(fmt::format("the header '{}' has {} columns but --columns names {}", quoted,
                       cells.size(), format_.columns.size()));
    parser_.SetDelimiter(delimiter);
    columns_text_ += fmt::format(", over the header on line {}", line_number_);
    return;
  }
  std::vector<NamedColumn> columns;
  std::vector<std::string> mapping;
  for (const std::string& cell : cells) {
    const NamedColumn c = RecognizeColumnName(cell);
    columns.push_back(c);
    if (c.column == SampleColumn::kIgnore) {
      ignored_.push_back(detail::PrintableExcerpt(cell, 24));
      continue;
    }
    const std::string name = ColumnListName(c);
    mapping.push_back(cell == name ? name : fmt::format("{}={}", detail::PrintableExcerpt(cell, 24), name));
    if ((c.column == SampleColumn::kAx || c.column == SampleColumn::kAy ||
         c.column == SampleColumn::kAz) && unit_hint_.empty())
      unit_hint_ = HeaderUnitHint(cell);
  }
  bool any_accel = false;
  for (const NamedColumn& c : columns)
    any_accel |= c.column == SampleColumn::kAx || c.column == SampleColumn::kAy || c.column == SampleColumn::kAz;
  if (!any_accel) {
    fail(fmt::format("'{}' is neither data nor a header naming the accelerometer columns (ax, "
                     "ay, az, or acc_x, AccX, ...); skip leading lines with --skip-rows N, or "
                     "name the columns with --columns", quoted));
  }
  if (columns.size() > static_cast<size_t>(detail::SampleLineParser::kMaxColumns))
    fail(fmt::format("the header has {} columns; at most {} are read", columns.size(),
                     int(detail::SampleLineParser::kMaxColumns)));
  if (std::string e = CheckColumnLayout(columns, cells); !e.empty())
    fail(fmt::format("the header '{}': {}; name the columns with --columns", quoted, e));
  parser_.UseColumns(columns, cells);
  parser_.SetDelimiter(delimiter);
  if (!parser_.has_t_column() && !time_from_rate_)
    fail(fmt::format("the header '{}' names no time column: give the sample rate with "
                     "--rate-hz HZ", quoted));
  columns_text_ = fmt::format("{} from the header on line {}", JoinNames(mapping), line_number_);
  if (!unit_hint_.empty() && unit_hint_ != format_.unit.Name() && format_.unit.is_counts() &&
      !format_.unit_declared) {
    fail(fmt::format("the header '{}' says the readings are in {}: declare it with --unit {} "
                     "(or --unit counts to take them as counts)", quoted, unit_hint_, unit_hint_));
  }
}

void SampleReader::ParseData(std::string_view line, std::vector<Sample>* out) {
  const long row = data_rows_++;
  Sample s;
  size_t t_offset = parser_.Parse(line, line_number_, &s);
  layout_decided_ = true;
  if (!format_.require_temp_c.empty() && !std::isfinite(s.temp_c))
    throw InputError(source_name_, line_number_, 0, format_.require_temp_c);
  if (first_magnitudes_.size() < kHintRows) {
    first_magnitudes_.push_back(s.raw_counts.norm());
    first_fractional_ |= s.raw_counts != s.raw_counts.array().round().matrix();
  }
  if (time_from_rate_) {
    s.t_s = static_cast<double>(row) / format_.rate_hz;
    t_offset = 0;
  }
  time_check_.Add(s, line, line_number_, t_offset, out, &time_errors_);
  if (!time_errors_.empty()) HandleTimeErrors();
}

void SampleReader::HandleTimeErrors() {
  if (time_errors_.empty()) return;
  std::vector<InputError> errors = std::move(time_errors_);
  time_errors_.clear();
  if (on_malformed_ == OnMalformed::kThrow) throw errors.front();
  for (const InputError& e : errors) Malformed(e);
}

void SampleReader::Overlong() {
  ++line_number_;
  const std::string why =
      fmt::format("more than {} bytes without an end of line (binary data, or not a text "
                  "recording?)", format_.max_line_bytes);
  const InputError error(source_name_, line_number_, 1, why);
  if (on_malformed_ == OnMalformed::kThrow) throw error;
  Malformed(error, fmt::format("line {}: more than {} bytes without an end of line (binary "
                               "data or a wrong baud rate?); skipped", line_number_,
                               format_.max_line_bytes));
}

void SampleReader::Malformed(const InputError& e, std::string complaint) {
  ++malformed_;
  last_malformed_ = complaint.empty()
                        ? detail::PrintableExcerpt(fmt::format("line {}, column {}: {}", e.line(),
                                                               e.column(), e.message()), 200)
                        : std::move(complaint);
  if (error_sink_) error_sink_(e);
}

ReadingSummary SampleReader::Summary() const {
  ReadingSummary s;
  s.source_name = source_name_;
  s.columns = columns_text_;
  if (!format_.HasExplicitLayout() && parser_.positional() && parser_.fields_per_line() > 0)
    s.columns = parser_.fields_per_line() == 4 ? "t ax ay az (the protocol's order)"
                                              : "t ax ay az temp_c (the protocol's order)";
  s.ignored = ignored_;
  s.unit_hint = unit_hint_;
  s.skipped_rows = skipped_rows_;
  s.data_rows = data_rows_;
  s.samples = time_check_.delivered();
  s.malformed = malformed_;
  s.rate_hz = time_from_rate_ ? format_.rate_hz : kNaN;
  s.median_interval_s = time_check_.MedianIntervalS();
  s.repaired_ties = time_check_.repaired();
  s.stamp_step_s = time_check_.stamp_step_s();
  s.unit = format_.unit;
  if (format_.unit.is_counts() && !format_.unit_declared && first_fractional_ &&
      !first_magnitudes_.empty()) {
    std::vector<double> m = first_magnitudes_;
    std::nth_element(m.begin(), m.begin() + static_cast<std::ptrdiff_t>(m.size() / 2), m.end());
    const double median = m[m.size() / 2];
    if (median > 5.0 && median < 15.0)
      s.converted_hint = fmt::format("the readings look like m/s^2 already (magnitude {:.3g} with "
                                     "fractions), not ADC counts: declare --unit m/s^2 (or "
                                     "--unit counts if they are counts)", median);
    else if (median > 0.5 && median < 1.5)
      s.converted_hint = fmt::format("the readings look like g already (magnitude {:.3g} with "
                                     "fractions), not ADC counts: declare --unit g (or --unit "
                                     "counts if they are counts)", median);
  }
  return s;
}

}  // namespace accelcal
