#include "accelcal/acquire/mavlink/mavlink_frame.h"

#include <fmt/format.h>

#include "accelcal/acquire/mavlink/x25_crc.h"
#include "accelcal/base/error.h"

namespace accelcal::mavlink {
namespace {

constexpr std::uint8_t kStxV1 = 0xFE;
constexpr std::uint8_t kStxV2 = 0xFD;
constexpr std::uint8_t kIncompatSigned = 0x01;
constexpr size_t kSignatureBytes = 13;
constexpr size_t kHeaderV1 = 6, kHeaderV2 = 10;
// Kept in the buffer at most before the read bytes are compacted.
constexpr size_t kCompactAfter = 4096;

std::string From(const Frame& f) {
  return fmt::format("from system {} component {} (seq {})", f.system, f.component, f.seq);
}

}  // namespace

void FrameParser::Reset() {
  buffer_.clear();
  start_ = 0;
  garbage_run_ = 0;
}

void FrameParser::Complain(std::string text, long* bad) {
  last_complaint_ = std::move(text);
  ++*bad;
}

void FrameParser::EndGarbage(long* bad) {
  if (garbage_run_ == 0) return;
  if (after_bad_crc_) {
    // The rest of a frame whose CRC failed: the same event, said once.
    last_complaint_ += fmt::format(" ({} bytes after it skipped)", garbage_run_);
    after_bad_crc_ = false;
    garbage_run_ = 0;
    return;
  }
  Complain(fmt::format("{} byte{} that {} not MAVLink frames skipped", garbage_run_,
                       garbage_run_ == 1 ? "" : "s", garbage_run_ == 1 ? "is" : "are"),
           bad);
  garbage_run_ = 0;
}

void FrameParser::Feed(const std::uint8_t* bytes, size_t count, std::vector<Frame>* out,
                       long* bad) {
  buffer_.insert(buffer_.end(), bytes, bytes + count);
  while (start_ < buffer_.size()) {
    const std::uint8_t b = buffer_[start_];
    if (b != kStxV1 && b != kStxV2) {
      ++garbage_run_;
      ++counters_.garbage_bytes;
      ++start_;
      continue;
    }
    size_t used = 0;
    const Step step = TryFrame(out, &used);
    if (step == Step::kNeedMore) break;
    if (step == Step::kSkipByte) {
      // A start marker that begins no good frame: garbage too.
      ++garbage_run_;
      ++counters_.garbage_bytes;
      ++start_;
      continue;
    }
    EndGarbage(bad);
    if (step == Step::kFrame) after_bad_crc_ = false;
    if (step == Step::kBad) {
      ++*bad;
      if (used == 0) used = 1;
    }
    start_ += used;
  }
  // A garbage run that reaches the end of what arrived is reported once it is long; a short one
  // may still be the start of a frame's bytes being looked through.
  if (garbage_run_ >= 256) EndGarbage(bad);
  if (start_ >= kCompactAfter || start_ == buffer_.size()) {
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(start_));
    start_ = 0;
  }
}

FrameParser::Step FrameParser::TryFrame(std::vector<Frame>* out, size_t* used) {
  const std::uint8_t* p = buffer_.data() + start_;
  const size_t avail = buffer_.size() - start_;
  const bool v2 = p[0] == kStxV2;
  const size_t header = v2 ? kHeaderV2 : kHeaderV1;
  if (avail < header) return Step::kNeedMore;
  Frame f;
  f.version = v2 ? 2 : 1;
  f.sent_length = p[1];
  std::uint8_t incompat = 0;
  if (v2) {
    incompat = p[2];
    f.seq = p[4];
    f.system = p[5];
    f.component = p[6];
    f.message = static_cast<std::uint32_t>(p[7]) | (static_cast<std::uint32_t>(p[8]) << 8) |
                (static_cast<std::uint32_t>(p[9]) << 16);
    f.signed_frame = (incompat & kIncompatSigned) != 0;
  } else {
    f.seq = p[2];
    f.system = p[3];
    f.component = p[4];
    f.message = p[5];
  }
  const size_t total = header + static_cast<size_t>(f.sent_length) + 2 +
                       (f.signed_frame ? kSignatureBytes : 0);
  if (avail < total) return Step::kNeedMore;
  const MessageSpec* spec = FindMessage(f.message);
  if (spec == nullptr) {
    // Not ours: its CRC cannot be checked, so garbage that happens to hold a start marker looks
    // the same. It is skipped by its length only when it looks like a frame (v2 flags that exist,
    // and the next frame's start marker right after it, when that has arrived); otherwise the
    // marker is taken for garbage, so that a burst cannot swallow the good frames after it.
    const bool flags_ok = (incompat & ~kIncompatSigned) == 0;
    const bool next_ok = avail == total || buffer_[start_ + total] == kStxV1 ||
                         buffer_[start_ + total] == kStxV2;
    if (!flags_ok || !next_ok) return Step::kSkipByte;
    ++counters_.other_messages;
    counters_.last_other_message = f.message;
    *used = total;
    return Step::kFrame;
  }
  X25Crc crc;
  crc.Add(p + 1, header - 1 + static_cast<size_t>(f.sent_length));
  crc.Add(spec->crc_extra);
  const size_t crc_at = header + static_cast<size_t>(f.sent_length);
  const std::uint16_t sent_crc = static_cast<std::uint16_t>(p[crc_at] | (p[crc_at + 1] << 8));
  if (crc.value() != sent_crc) {
    ++counters_.bad_crc;
    last_complaint_ = fmt::format("bad CRC on a {} frame {} ({} payload bytes)", spec->name,
                                  From(f), f.sent_length);
    after_bad_crc_ = true;
    *used = 1;
    return Step::kBad;
  }
  *used = total;
  if ((incompat & ~kIncompatSigned) != 0) {
    ++counters_.bad_flags;
    last_complaint_ = fmt::format("a {} frame {} with incompatibility flags 0x{:02x}, which "
                                  "MAVLink 2 says to drop", spec->name, From(f), incompat);
    return Step::kBad;
  }
  const bool too_long = f.sent_length > spec->max_length;
  const bool v1_short = !v2 && f.sent_length < spec->base_length;
  if (too_long || v1_short || f.sent_length == 0) {
    ++counters_.wrong_length;
    last_complaint_ = fmt::format("a {} frame {} with {} payload bytes ({} {} expected)",
                                  spec->name, From(f), f.sent_length,
                                  too_long ? "at most" : "at least",
                                  too_long ? spec->max_length : spec->base_length);
    return Step::kBad;
  }
  f.payload.assign(p + header, p + header + f.sent_length);
  f.payload.resize(static_cast<size_t>(spec->max_length), 0);
  ++counters_.frames;
  if (f.signed_frame) ++counters_.signed_frames;
  if (!v2) ++counters_.v1_frames;
  out->push_back(std::move(f));
  return Step::kFrame;
}

std::vector<std::uint8_t> FrameWriter::Encode(std::uint32_t message, const Payload& payload,
                                              int version) {
  const MessageSpec* spec = FindMessage(message);
  if (spec == nullptr) throw Error(fmt::format("cannot encode MAVLink message {}", message));
  Payload body = payload;
  body.resize(static_cast<size_t>(version == 1 ? spec->base_length : spec->max_length), 0);
  if (version == 2)
    while (body.size() > 1 && body.back() == 0) body.pop_back();
  std::vector<std::uint8_t> frame;
  if (version == 1) {
    frame = {kStxV1, static_cast<std::uint8_t>(body.size()), seq_, system_, component_,
             static_cast<std::uint8_t>(message)};
  } else {
    frame = {kStxV2, static_cast<std::uint8_t>(body.size()), 0, 0, seq_, system_, component_,
             static_cast<std::uint8_t>(message & 0xFF), static_cast<std::uint8_t>((message >> 8) & 0xFF),
             static_cast<std::uint8_t>((message >> 16) & 0xFF)};
  }
  ++seq_;
  frame.insert(frame.end(), body.begin(), body.end());
  X25Crc crc;
  crc.Add(frame.data() + 1, frame.size() - 1);
  crc.Add(spec->crc_extra);
  frame.push_back(static_cast<std::uint8_t>(crc.value() & 0xFF));
  frame.push_back(static_cast<std::uint8_t>(crc.value() >> 8));
  return frame;
}

}  // namespace accelcal::mavlink
