// The one reader of sample tables: recordings (`fit --recording`, `allan`, `noise`), the lines
// `apply` reads, and the byte streams of the file, standard-input, serial and TCP sources. Bytes
// in, as they come (a whole file, blocks, or reads of any size), samples out.
//
// What it reads (docs/formats.md, "Reading other people's files"):
// - Lines ended by LF or CRLF; a UTF-8 byte-order mark at the start is skipped; the first
//   `skip_rows` lines are ignored whatever they hold; blank lines and lines whose first
//   non-blank character is '#' (comments) are skipped anywhere.
// - The columns: given (SampleFormat::columns), or named by a header row (the first line that
//   is neither skipped, blank, a comment nor data: sample_columns.h recognises the names; what
//   it does not know is ignored and listed), or the protocol's positional `t ax ay az [temp_c]`.
//   A first line that is not data and names no accelerometer columns is an error that says so.
// - Fields and values as detail::SampleLineParser reads them (blanks, commas, semicolons, tabs).
// - Time: from the t column, or t = row / rate_hz with a rate given (the row index counts every
//   data row from 0, a malformed one too). Checked and repaired by detail::SampleTimeCheck: a t
//   that goes back is an error, repeated stamps of a rounding logger are spread within their
//   step.
// - A line longer than SampleFormat::max_line_bytes is not a text line (binary data, a wrong
//   baud rate): the reading stops there (kThrow) or skips it to the next newline (kSkip).
//
// Malformed input, by policy: kThrow (files) throws the first InputError (FILE:LINE:COLUMN) and
// reads nothing more; kSkip (live streams, `apply`) counts the line as malformed, keeps the
// latest complaint ("line 12, column 5: field 'ax': 'x' is not a number") and goes on.
//
// Speed: lines are parsed in place from the caller's buffer (no allocation per line); Consume()
// lets a block reader keep a partial line itself, so that nothing is copied. Once a long file's
// reading is settled (layout, header, the first rows' unit hint), its plain lines take a lane:
// read one after another straight from the buffer, most by the shape learned from the lines
// before (line_shapes.h), each handled as the line-by-line path would (the same samples, time
// checks, counts and errors; tests/unit/base/reader_lane_test.cpp holds the two together). Samples
// are appended to the caller's vector (reserve it).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/sample_format.h"
#include "accelcal/base/sample_line_parser.h"
#include "accelcal/base/sample_time_check.h"

namespace accelcal {

// What a reading understood, for the one line every reader prints (Describe()).
struct ReadingSummary {
  std::string source_name;
  std::string columns;           // "t ax ay az (the protocol's order)", "from the header ..."
  std::vector<std::string> ignored;  // header names of the columns ignored
  std::string unit_hint;         // the unit the header states for ax..az ("m/s^2", "g"), if any
  // Readings taken as counts (the unit not declared) that look converted already: magnitudes
  // about 9.8 or 1 with fractions. In words, naming --unit; empty otherwise.
  std::string converted_hint;
  long skipped_rows = 0;
  long data_rows = 0;
  long samples = 0;
  long malformed = 0;            // kSkip: lines skipped as malformed
  double rate_hz = kNaN;         // given (t from the row index); NaN: t from its column
  double median_interval_s = kNaN;  // of the first samples
  long repaired_ties = 0;        // repeated stamps spread within their step
  double stamp_step_s = kNaN;    // the finest step of the stamps
  ReadingUnit unit;
  // A bag's reading (bags/bag_sample_stream.h): what the samples are instead of a table's
  // columns ("topic /imu (sensor_msgs/msg/Imu) of an MCAP file, zstd chunks"), where t comes
  // from ("t from the header stamps"), and what was read around (a cut file); empty for a table.
  std::string origin;
  std::string time_source;
  std::vector<std::string> notes;

  // One line: "rec.txt: 51175 samples; columns t ax ay az (the protocol's order); t from its
  // column, median interval 0.01 s (100 Hz); counts".
  std::string Describe() const;
};

class SampleReader {
 public:
  enum class OnMalformed { kThrow, kSkip };

  // `format` must be valid (SampleFormat::Validate()); throws accelcal::Error otherwise.
  SampleReader(std::string source_name, const SampleFormat& format, OnMalformed on_malformed);

  // Parses the complete lines at the start of `text` (and, when `final`, an unterminated last
  // one) and appends their samples to *out. Returns the bytes consumed: the rest is a partial
  // line (shorter than the line limit) that the caller passes again, with what follows it.
  size_t Consume(std::string_view text, bool final, std::vector<Sample>* out);
  // For reads of any size: keeps a partial line itself (copied, at most the line limit).
  void Feed(std::string_view bytes, std::vector<Sample>* out);
  // The end of the input: a partial line counts; samples held while repeated stamps were judged
  // are delivered. Call once, after the last Consume or Feed.
  void Finish(std::vector<Sample>* out);
  // A live link dropped: its unterminated line is a fragment, not data; forget it.
  void DiscardPartial();

  // Called for each comment line with its text (no terminator) and the number of data rows
  // before it (apply passes comments through in place). Optional.
  using CommentSink = std::function<void(std::string_view comment, long data_rows_before)>;
  void set_comment_sink(CommentSink sink) { comment_sink_ = std::move(sink); }

  // kSkip: called with each malformed line's error (as it would have been thrown). Optional.
  using ErrorSink = std::function<void(const InputError& error)>;
  void set_error_sink(ErrorSink sink) { error_sink_ = std::move(sink); }

  long line_number() const { return line_number_; }
  long malformed() const { return malformed_; }
  const std::string& last_malformed() const { return last_malformed_; }
  ReadingSummary Summary() const;

 private:
  void ProcessLine(std::string_view line, std::vector<Sample>* out);
  bool LaneOpen(const char* p, const char* end) const;
  const char* TakePaddedLines(const char* p, const char* end, std::vector<Sample>* out);
  bool TakeHeaderOrDecide(std::string_view line);
  void UseHeader(std::string_view line);
  void ParseData(std::string_view line, std::vector<Sample>* out);
  void Overlong();
  void Malformed(const InputError& e, std::string complaint = {});
  void HandleTimeErrors();

  std::string source_name_;
  SampleFormat format_;
  OnMalformed on_malformed_;
  detail::SampleLineParser parser_;
  detail::SampleTimeCheck time_check_;
  CommentSink comment_sink_;
  ErrorSink error_sink_;
  bool layout_decided_ = false;
  bool time_from_rate_ = false;
  long line_number_ = 0;
  long skipped_rows_ = 0;
  long data_rows_ = 0;
  long malformed_ = 0;
  std::string last_malformed_;
  std::string columns_text_;
  std::vector<std::string> ignored_;
  std::string unit_hint_;
  std::vector<InputError> time_errors_;
  std::vector<double> first_magnitudes_;  // |raw| of the first rows (converted_hint)
  bool first_fractional_ = false;         // one of them is not a whole number
  std::string partial_;    // Feed: bytes of the unterminated line so far
  bool skipping_ = false;  // inside an overlong line: drop bytes up to the next newline
  long lane_closed_until_line_ = 0;  // the lane took no line: not before this line again
};

}  // namespace accelcal
