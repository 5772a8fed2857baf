#include "accelcal/acquire/source/stream_source.h"

#include <algorithm>
#include <cmath>

#include "accelcal/acquire/source/wall_clock.h"
#include "accelcal/base/sample_reader.h"

namespace accelcal {
namespace {

using source_detail::SleepS;
using source_detail::kMinPacedBurstS;
using source_detail::WallNowS;

// Paced replay: parsed samples held ahead of the clock at most (bounds memory on big files).
constexpr size_t kMaxPacedBacklog = 20000;

}  // namespace

StreamSource::StreamSource(std::unique_ptr<ByteLink> link, const SourceOptions& options,
                           Pacing pacing)
    : reader_(std::move(link), options),
      pacing_(pacing),
      lines_(reader_.Describe(), options.max_line_bytes, options.format),
      tracker_(options.gap_factor, options.dead_after_s, WallNowS()),
      pace_origin_wall_s_(kNaN),
      pace_origin_t_s_(kNaN) {}

StreamSource::~StreamSource() = default;

std::string StreamSource::DescribeReading() const { return lines_.Summary().Describe(); }

ReadResult StreamSource::Read(double timeout_s, std::vector<Sample>* out) {
  ReadResult result;
  result_ = &result;
  const double deadline_s = WallNowS() + std::max(0.0, timeout_s);
  for (;;) {
    if (!reader_.input_done() && !Backlogged()) reader_.Fill(deadline_s, *this);
    const double now_s = WallNowS();
    const bool paced = pacing_ == Pacing::kByT;
    if (!paced || now_s >= last_burst_wall_s_ + kMinPacedBurstS || now_s >= deadline_s) {
      Deliver(now_s, out, &result);
      if (paced && result.samples > 0) last_burst_wall_s_ = now_s;
    }
    if (reader_.input_done() && pending() == 0) tracker_.OnEnded(&result);
    if (result.samples > 0 || status().link == LinkState::kEnded || now_s >= deadline_s) break;
    // Waiting on the clock rather than on the link: a paced replay ahead of time.
    if (pending() > 0 && (Backlogged() || reader_.input_done())) {
      const double wake_s = std::max(NextDueWallS(), last_burst_wall_s_ + kMinPacedBurstS);
      SleepS(std::min(deadline_s, wake_s) - now_s);
    }
  }
  tracker_.Tick(WallNowS(), &result);
  result_ = nullptr;
  return result;
}

void StreamSource::OnLinkOpen() { tracker_.OnLinkUp(WallNowS(), result_ ? result_ : &scratch_); }

void StreamSource::OnLinkOpenFailed(const std::string& error) { tracker_.OnOpenFailed(error); }

void StreamSource::OnBytes(std::string_view bytes) {
  LineStream::FeedResult fed;
  lines_.Feed(bytes, &parsed_, &fed);
  tracker_.OnMalformed(fed.malformed, fed.last_malformed, result_ ? result_ : &scratch_);
}

// A link that reopens loses its unterminated last line; a finished stream's still counts.
void StreamSource::OnLinkEnd(const std::string& described, bool failed, bool reopens) {
  ReadResult* result = result_ ? result_ : &scratch_;
  if (reopens) {
    lines_.DiscardPartial();
    tracker_.OnLinkLost(described, result);
    return;
  }
  LineStream::FeedResult fed;
  lines_.Finish(&parsed_, &fed);
  tracker_.OnMalformed(fed.malformed, fed.last_malformed, result);
  if (failed) tracker_.OnOpenFailed(described);
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
