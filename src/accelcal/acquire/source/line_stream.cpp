#include "accelcal/acquire/source/line_stream.h"

#include <cstring>

#include <fmt/format.h>

#include "accelcal/base/sample_line_parser.h"
#include "accelcal/base/error.h"

namespace accelcal {

std::string PrintableText(std::string_view text, size_t max_chars) {
  std::string out;
  out.reserve(std::min(text.size(), max_chars));
  for (char c : text) {
    if (out.size() >= max_chars) {
      out += "...";
      break;
    }
    const auto u = static_cast<unsigned char>(c);
    out += (u >= 0x20 && u < 0x7f) ? c : '?';
  }
  return out;
}

LineStream::LineStream(std::string source_name, long max_line_bytes)
    : parser_(std::make_unique<detail::SampleLineParser>(std::move(source_name))),
      max_line_bytes_(max_line_bytes) {}

LineStream::~LineStream() = default;

void LineStream::Feed(std::string_view bytes, std::vector<Sample>* out, FeedResult* result) {
  while (!bytes.empty()) {
    const void* nl = std::memchr(bytes.data(), '\n', bytes.size());
    if (nl == nullptr) {
      AppendPartial(bytes, result);
      return;
    }
    const size_t n = static_cast<size_t>(static_cast<const char*>(nl) - bytes.data());
    if (skipping_) {
      skipping_ = false;  // the overlong line ends here; it was counted when it overflowed
    } else if (partial_.empty()) {
      ConsumeLine(bytes.substr(0, n), out, result);  // the common case: parse in place
    } else {
      AppendPartial(bytes.substr(0, n), result);
      if (!skipping_) ConsumeLine(partial_, out, result);
      skipping_ = false;
      partial_.clear();
    }
    bytes.remove_prefix(n + 1);
  }
}

void LineStream::AppendPartial(std::string_view bytes, FeedResult* result) {
  if (skipping_) return;
  if (static_cast<long>(partial_.size() + bytes.size()) > max_line_bytes_) {
    CountOverlong(result);
    return;
  }
  partial_.append(bytes);
}

void LineStream::CountOverlong(FeedResult* result) {
  ++line_number_;
  ++result->malformed;
  result->last_malformed =
      fmt::format("line {}: more than {} bytes without an end of line (binary data or a wrong "
                  "baud rate?); skipped", line_number_, max_line_bytes_);
  partial_.clear();
  skipping_ = true;
}

void LineStream::ConsumeLine(std::string_view line, std::vector<Sample>* out,
                             FeedResult* result) {
  ++line_number_;
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (static_cast<long>(line.size()) > max_line_bytes_) {
    // A whole overlong line in one read: the same verdict as one split across reads.
    --line_number_;
    CountOverlong(result);
    skipping_ = false;
    return;
  }
  Sample sample;
  try {
    if (!parser_->Parse(line, line_number_, &sample)) return;
  } catch (const InputError& e) {
    ++result->malformed;
    result->last_malformed =
        PrintableText(fmt::format("line {}, column {}: {}", e.line(), e.column(), e.message()));
    return;
  }
  out->push_back(sample);
  ++result->samples;
}

void LineStream::Finish(std::vector<Sample>* out, FeedResult* result) {
  if (!skipping_ && !partial_.empty()) ConsumeLine(partial_, out, result);
  partial_.clear();
  skipping_ = false;
}

void LineStream::DiscardPartial() {
  partial_.clear();
  skipping_ = false;
}

}  // namespace accelcal
