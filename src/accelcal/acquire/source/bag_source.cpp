#include "accelcal/acquire/source/bag_source.h"

#include <algorithm>
#include <cmath>

#include "accelcal/acquire/source/wall_clock.h"
#include "accelcal/base/error.h"

namespace accelcal {

BagSource::BagSource(const std::string& path, const SourceOptions& options)
    : path_(path),
      realtime_(options.realtime),
      stream_(path, options.format),
      tracker_(options.gap_factor, options.dead_after_s, source_detail::WallNowS()),
      pace_origin_wall_s_(kNaN),
      pace_origin_t_s_(kNaN) {}

// The next chunk's samples; at the end, or at damage, the input is done.
void BagSource::Pull() {
  pending_.clear();
  next_ = 0;
  try {
    if (!stream_.Next(&pending_)) input_done_ = true;
  } catch (const Error& e) {
    tracker_.OnOpenFailed(e.what());
    input_done_ = true;
  }
}

size_t BagSource::Due(double now_s) const {
  if (!realtime_) return pending_.size();
  size_t end = next_;
  while (end < pending_.size() &&
         pending_[end].t_s - pace_origin_t_s_ <= now_s - pace_origin_wall_s_)
    ++end;
  return end;
}

ReadResult BagSource::Read(double timeout_s, std::vector<Sample>* out) {
  using source_detail::WallNowS;
  ReadResult result;
  const double deadline_s = WallNowS() + std::max(0.0, timeout_s);
  if (!up_) {
    tracker_.OnLinkUp(WallNowS(), &result);
    up_ = true;
  }
  for (;;) {
    if (next_ == pending_.size() && !input_done_) Pull();
    const double now_s = WallNowS();
    if (realtime_ && next_ < pending_.size() && std::isnan(pace_origin_wall_s_)) {
      pace_origin_wall_s_ = now_s;
      pace_origin_t_s_ = pending_[next_].t_s;
    }
    const size_t end = Due(now_s);
    if (end > next_) {
      out->insert(out->end(), pending_.begin() + static_cast<std::ptrdiff_t>(next_),
                  pending_.begin() + static_cast<std::ptrdiff_t>(end));
      tracker_.OnSamples(pending_.data() + next_, static_cast<long>(end - next_), now_s, &result);
      next_ = end;
    }
    if (input_done_ && next_ == pending_.size()) {
      tracker_.OnEnded(&result);
      break;
    }
    if (result.samples > 0 || now_s >= deadline_s) break;
    // Paced and ahead of the clock: wait for the next sample's time (or the deadline).
    const double due_s = pace_origin_wall_s_ + (pending_[next_].t_s - pace_origin_t_s_);
    source_detail::SleepS(std::min(deadline_s, std::max(due_s, now_s + source_detail::kMinPacedBurstS)) - now_s);
  }
  tracker_.Tick(WallNowS(), &result);
  return result;
}

}  // namespace accelcal
