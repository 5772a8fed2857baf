// The line-protocol core of every byte-stream source (stdin, file, serial, TCP): bytes in, as
// they arrive in reads of any size, samples out.
//
// Protocol (docs/formats.md, "Sample sources"): one sample per line `t ax ay az [temp_c]`, fields
// separated by blanks and/or one comma, t in s strictly increasing, raw counts, '#' comments,
// blank lines, LF or CRLF; or what a SampleFormat says (columns, a header row, skipped rows, a
// rate for a stream without time). The lines go through the one sample reader
// (base/sample_reader.h, the recording reader's), so the rules are the same everywhere.
//
// Bad input is never fatal: a malformed line (bad number, wrong field count, t not increasing)
// is counted and its complaint kept, and the stream goes on. A run of more than max_line_bytes
// without a newline (binary noise, a wrong baud rate) counts as one malformed line and is
// dropped up to the next newline, so garbage can neither wedge the stream nor grow memory.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/sample_format.h"

namespace accelcal {

class SampleReader;
struct ReadingSummary;

class LineStream {
 public:
  struct FeedResult {
    long samples = 0;            // appended to the caller's vector
    long malformed = 0;          // malformed lines
    std::string last_malformed;  // "line 12, column 5: field 'ax': 'x' is not a number"
  };

  // source_name names the stream in the reader's summary. `format` must be valid; its
  // max_line_bytes is replaced by `max_line_bytes` (>= 64).
  LineStream(std::string source_name, long max_line_bytes, const SampleFormat& format = {});
  ~LineStream();
  LineStream(const LineStream&) = delete;
  LineStream& operator=(const LineStream&) = delete;

  // Consumes `bytes`; every line completed by them is parsed, samples appended to *out.
  void Feed(std::string_view bytes, std::vector<Sample>* out, FeedResult* result);
  // End of the data: a last line without a newline still counts.
  void Finish(std::vector<Sample>* out, FeedResult* result);
  // The link dropped: an unterminated line is a fragment, not data; forget it.
  void DiscardPartial();

  // Lines seen so far (data, comments, malformed), 1-based number of the latest.
  long line_number() const;
  // What the stream's reading understood so far (columns, rate, repairs).
  ReadingSummary Summary() const;

 private:
  void Collect(size_t before, const std::vector<Sample>& out, FeedResult* result);

  std::unique_ptr<SampleReader> reader_;
  long malformed_seen_ = 0;  // the reader's malformed count already reported
};

// A complaint fit for a status line: non-printable bytes (garbage) shown as '?', at most
// `max_chars` characters (base/text_scan.h's PrintableExcerpt).
std::string PrintableText(std::string_view text, size_t max_chars = 160);

}  // namespace accelcal
