#include "accelcal/acquire/source/status_tracker.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace accelcal {
namespace {

// The median needs a few intervals before it means anything; until then no gaps are judged.
constexpr long kMinIntervalsForMedian = 4;
// Re-sorting the window for every sample would cost more than the parse; every 16th is plenty.
constexpr long kRefreshEvery = 16;

}  // namespace

StatusTracker::StatusTracker(double gap_factor, double dead_after_s, double now_s)
    : gap_factor_(gap_factor), dead_after_s_(dead_after_s), quiet_since_s_(now_s) {}

void StatusTracker::OnSamples(const Sample* samples, long count, double now_s,
                              ReadResult* result) {
  if (count <= 0) return;
  for (long i = 0; i < count; ++i) {
    const double t_s = samples[i].t_s;
    if (!std::isnan(status_.last_t_s)) {
      const double dt_s = t_s - status_.last_t_s;
      if (!std::isnan(median_dt_s_) && dt_s > gap_factor_ * median_dt_s_) {
        ++status_.gaps;
        ++result->gaps;
        status_.last_gap = {status_.last_t_s, t_s, dt_s - median_dt_s_};
      }
      AddInterval(dt_s);
    }
    status_.last_t_s = t_s;
  }
  status_.samples_total += count;
  result->samples += count;
  last_sample_wall_s_ = now_s;
  quiet_since_s_ = now_s;
  status_.since_last_sample_s = 0.0;
  if (status_.link != LinkState::kEnded) BecomeUp(result);
}

void StatusTracker::AddInterval(double dt_s) {
  intervals_s_[static_cast<size_t>(intervals_seen_ % kRateWindow)] = dt_s;
  ++intervals_seen_;
  if (++since_refresh_ >= kRefreshEvery || intervals_seen_ <= kRateWindow) RefreshMedian();
}

void StatusTracker::RefreshMedian() {
  since_refresh_ = 0;
  const long n = std::min<long>(intervals_seen_, kRateWindow);
  if (n < kMinIntervalsForMedian) return;
  std::array<double, kRateWindow> sorted = intervals_s_;
  auto mid = sorted.begin() + n / 2;
  std::nth_element(sorted.begin(), mid, sorted.begin() + n);
  median_dt_s_ = *mid;
  status_.rate_hz = median_dt_s_ > 0.0 ? 1.0 / median_dt_s_ : kNaN;
}

void StatusTracker::OnMalformed(long count, const std::string& last, ReadResult* result) {
  if (count <= 0) return;
  status_.malformed_lines += count;
  result->malformed += count;
  status_.last_malformed = last;
}

void StatusTracker::BecomeUp(ReadResult* result) {
  if (status_.link == LinkState::kDead) {
    result->reconnected = true;
    ++status_.reconnects;
  }
  status_.link = LinkState::kUp;
  status_.link_error.clear();
}

void StatusTracker::OnLinkUp(double now_s, ReadResult* result) {
  quiet_since_s_ = std::max(quiet_since_s_, now_s);
  BecomeUp(result);
}

void StatusTracker::OnLinkLost(const std::string& why, ReadResult* result) {
  result->link_lost = true;
  if (status_.link != LinkState::kDead) result->went_dead = true;
  status_.link = LinkState::kDead;
  status_.link_error = why;
  dead_of_silence_ = false;
}

void StatusTracker::OnOpenFailed(const std::string& why) {
  status_.link_error = why;
  dead_of_silence_ = false;
}

void StatusTracker::OnEnded(ReadResult* result) {
  if (status_.link == LinkState::kEnded) return;
  status_.link = LinkState::kEnded;
  status_.link_error.clear();
  result->ended = true;
}

void StatusTracker::Tick(double now_s, ReadResult* result, const std::string& silence) {
  if (!std::isnan(last_sample_wall_s_)) status_.since_last_sample_s = now_s - last_sample_wall_s_;
  const bool waiting = status_.link == LinkState::kUp || status_.link == LinkState::kConnecting;
  if (!waiting || now_s - quiet_since_s_ <= dead_after_s_) return;
  status_.link = LinkState::kDead;
  result->went_dead = true;
  // A connection error says more than the silence it causes; keep it when there is one.
  dead_of_silence_ = status_.link_error.empty();
  if (dead_of_silence_)
    status_.link_error = fmt::format("no sample for {:.1f} s", now_s - quiet_since_s_) +
                         (silence.empty() ? "" : ": " + silence);
}

void StatusTracker::OnSilenceReason(const std::string& silence, double now_s, ReadResult* result) {
  if (status_.link == LinkState::kDead && dead_of_silence_)
    status_.link_error = fmt::format("no sample for {:.1f} s: {}", now_s - quiet_since_s_, silence);
  OnNotice(silence, result, SourceNoticeKind::kDeviceSilent);
}

void StatusTracker::OnNotice(const std::string& notice, ReadResult* result, SourceNoticeKind kind) {
  status_.last_notice = notice;
  status_.last_notice_kind = kind;
  result->notice = true;
}

void StatusTracker::SetUnit(const ReadingUnit& unit, double resolution_counts) {
  status_.unit = unit;
  status_.resolution_counts = resolution_counts;
}

}  // namespace accelcal
