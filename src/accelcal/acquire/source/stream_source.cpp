#include "accelcal/acquire/source/stream_source.h"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "accelcal/acquire/source/wall_clock.h"
#include "accelcal/base/sample_reader.h"

namespace accelcal {
namespace {

using source_detail::SleepS;
using source_detail::kMinPacedBurstS;
using source_detail::WallNowS;

constexpr size_t kReadChunkBytes = 64 * 1024;
// Bytes taken from the link per Read call at most, so that a fire-hose cannot starve the caller.
constexpr size_t kMaxBytesPerCall = 1024 * 1024;
// Paced replay: parsed samples held ahead of the clock at most (bounds memory on big files).
constexpr size_t kMaxPacedBacklog = 20000;

int PollTimeoutMs(double deadline_s) {
  const double left_s = deadline_s - WallNowS();
  if (left_s <= 0.0) return 0;
  return static_cast<int>(std::ceil(std::min(left_s, 3600.0) * 1000.0));
}

}  // namespace

StreamSource::StreamSource(std::unique_ptr<ByteLink> link, const SourceOptions& options,
                           Pacing pacing)
    : link_(std::move(link)),
      pacing_(pacing),
      lines_(link_->Describe(), options.max_line_bytes, options.format),
      tracker_(options.gap_factor, options.dead_after_s, WallNowS()),
      backoff_(options.reconnect_initial_s, options.reconnect_max_s),
      pace_origin_wall_s_(kNaN),
      pace_origin_t_s_(kNaN),
      buffer_(kReadChunkBytes) {}

StreamSource::~StreamSource() { link_->Close(); }

std::string StreamSource::DescribeReading() const { return lines_.Summary().Describe(); }

ReadResult StreamSource::Read(double timeout_s, std::vector<Sample>* out) {
  ReadResult result;
  const double deadline_s = WallNowS() + std::max(0.0, timeout_s);
  for (;;) {
    if (!input_done_ && !Backlogged()) Fill(deadline_s, &result);
    const double now_s = WallNowS();
    const bool paced = pacing_ == Pacing::kByT;
    if (!paced || now_s >= last_burst_wall_s_ + kMinPacedBurstS || now_s >= deadline_s) {
      Deliver(now_s, out, &result);
      if (paced && result.samples > 0) last_burst_wall_s_ = now_s;
    }
    if (input_done_ && pending() == 0) tracker_.OnEnded(&result);
    if (result.samples > 0 || status().link == LinkState::kEnded || now_s >= deadline_s) break;
    // Waiting on the clock rather than on the link: a paced replay ahead of time.
    if (pending() > 0 && (Backlogged() || input_done_)) {
      const double wake_s = std::max(NextDueWallS(), last_burst_wall_s_ + kMinPacedBurstS);
      SleepS(std::min(deadline_s, wake_s) - now_s);
    }
  }
  tracker_.Tick(WallNowS(), &result);
  return result;
}

void StreamSource::Fill(double deadline_s, ReadResult* result) {
  if (!open_ && !TryOpen(deadline_s, result)) return;
  pollfd p{link_->fd(), POLLIN, 0};
  const int rc = poll(&p, 1, PollTimeoutMs(deadline_s));
  if (rc < 0 && errno != EINTR) {
    EndOfData(std::string("poll: ") + std::strerror(errno), true, result);
  } else if (rc > 0) {
    ReadAvailable(result);
  }
}

bool StreamSource::TryOpen(double deadline_s, ReadResult* result) {
  const double now_s = WallNowS();
  if (!backoff_.Due(now_s, deadline_s)) return false;
  std::string error;
  switch (link_->Open(std::max(0.0, deadline_s - now_s), &error)) {
    case ByteLink::OpenStep::kOpen:
      open_ = true;
      backoff_.Succeeded();
      tracker_.OnLinkUp(WallNowS(), result);
      return true;
    case ByteLink::OpenStep::kPending:
      return false;
    case ByteLink::OpenStep::kFailed:
      tracker_.OnOpenFailed(error);
      if (!link_->reopens()) input_done_ = true;
      backoff_.Failed(WallNowS());
      return false;
  }
  return false;
}

// Reads what is there (up to kMaxBytesPerCall) without waiting.
void StreamSource::ReadAvailable(ReadResult* result) {
  size_t taken = 0;
  while (open_ && taken < kMaxBytesPerCall) {
    const ssize_t n = read(link_->fd(), buffer_.data(), buffer_.size());
    if (n > 0) {
      taken += static_cast<size_t>(n);
      Parse(std::string_view(buffer_.data(), static_cast<size_t>(n)), result);
      pollfd p{link_->fd(), POLLIN, 0};
      if (poll(&p, 1, 0) <= 0) return;
    } else if (n == 0) {
      EndOfData(link_->reopens() ? "the other end closed the link" : "end of data", false,
                result);
    } else if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) {
      return;
    } else {
      EndOfData(std::string("read: ") + std::strerror(errno), true, result);
    }
  }
}

void StreamSource::Parse(std::string_view bytes, ReadResult* result) {
  LineStream::FeedResult fed;
  lines_.Feed(bytes, &parsed_, &fed);
  tracker_.OnMalformed(fed.malformed, fed.last_malformed, result);
}

// The link delivered its last byte (failed: with an error). A link that reopens is closed and
// retried; otherwise the stream is finished and its unterminated last line still counts.
void StreamSource::EndOfData(const std::string& why, bool failed, ReadResult* result) {
  link_->Close();
  open_ = false;
  const std::string described = link_->Describe() + ": " + why;
  if (link_->reopens()) {
    lines_.DiscardPartial();
    tracker_.OnLinkLost(described, result);
    backoff_.Failed(WallNowS());
    return;
  }
  LineStream::FeedResult fed;
  lines_.Finish(&parsed_, &fed);
  tracker_.OnMalformed(fed.malformed, fed.last_malformed, result);
  if (failed) tracker_.OnOpenFailed(described);
  input_done_ = true;
}

void StreamSource::Deliver(double now_s, std::vector<Sample>* out, ReadResult* result) {
  if (pending() == 0) return;
  size_t end = parsed_.size();
  if (pacing_ == Pacing::kByT) {
    if (std::isnan(pace_origin_wall_s_)) {
      pace_origin_wall_s_ = now_s;
      pace_origin_t_s_ = parsed_[next_].t_s;
    }
    end = next_;
    while (end < parsed_.size() &&
           parsed_[end].t_s - pace_origin_t_s_ <= now_s - pace_origin_wall_s_)
      ++end;
  }
  if (end == next_) return;
  out->insert(out->end(), parsed_.begin() + static_cast<std::ptrdiff_t>(next_),
              parsed_.begin() + static_cast<std::ptrdiff_t>(end));
  tracker_.OnSamples(parsed_.data() + next_, static_cast<long>(end - next_), now_s, result);
  next_ = end;
  if (next_ == parsed_.size()) {
    parsed_.clear();
    next_ = 0;
  } else if (next_ >= 4096 && 2 * next_ >= parsed_.size()) {
    // A paced replay never drains completely; drop what was delivered so memory stays bounded.
    parsed_.erase(parsed_.begin(), parsed_.begin() + static_cast<std::ptrdiff_t>(next_));
    next_ = 0;
  }
}

bool StreamSource::Backlogged() const {
  return pacing_ == Pacing::kByT && pending() >= kMaxPacedBacklog;
}

double StreamSource::NextDueWallS() const {
  if (pending() == 0 || std::isnan(pace_origin_wall_s_)) return WallNowS();
  return pace_origin_wall_s_ + (parsed_[next_].t_s - pace_origin_t_s_);
}

}  // namespace accelcal
