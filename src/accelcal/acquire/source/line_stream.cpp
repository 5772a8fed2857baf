#include "accelcal/acquire/source/line_stream.h"

#include "accelcal/base/sample_reader.h"
#include "accelcal/base/text_scan.h"

namespace accelcal {
namespace {

SampleFormat WithLineLimit(SampleFormat format, long max_line_bytes) {
  format.max_line_bytes = max_line_bytes;
  return format;
}

}  // namespace

std::string PrintableText(std::string_view text, size_t max_chars) {
  return detail::PrintableExcerpt(text, max_chars);
}

LineStream::LineStream(std::string source_name, long max_line_bytes, const SampleFormat& format)
    : reader_(std::make_unique<SampleReader>(std::move(source_name),
                                             WithLineLimit(format, max_line_bytes),
                                             SampleReader::OnMalformed::kSkip)) {}

LineStream::~LineStream() = default;

void LineStream::Feed(std::string_view bytes, std::vector<Sample>* out, FeedResult* result) {
  const size_t before = out->size();
  reader_->Feed(bytes, out);
  Collect(before, *out, result);
}

void LineStream::Finish(std::vector<Sample>* out, FeedResult* result) {
  const size_t before = out->size();
  reader_->Finish(out);
  Collect(before, *out, result);
}

void LineStream::DiscardPartial() { reader_->DiscardPartial(); }

long LineStream::line_number() const { return reader_->line_number(); }

ReadingSummary LineStream::Summary() const { return reader_->Summary(); }

void LineStream::Collect(size_t before, const std::vector<Sample>& out, FeedResult* result) {
  result->samples += static_cast<long>(out.size() - before);
  const long malformed = reader_->malformed() - malformed_seen_;
  if (malformed > 0) {
    result->malformed += malformed;
    result->last_malformed = reader_->last_malformed();
    malformed_seen_ = reader_->malformed();
  }
}

}  // namespace accelcal
