#include "accelcal/acquire/source/columns_sensor_set.h"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/acquire/source/wall_clock.h"

namespace accelcal {
namespace {

using source_detail::WallNowS;

constexpr size_t kSetReadChunkBytes = 64 * 1024;
constexpr size_t kSetMaxBytesPerCall = 1024 * 1024;

int SetPollTimeoutMs(double deadline_s) {
  const double left_s = deadline_s - WallNowS();
  if (left_s <= 0.0) return 0;
  return static_cast<int>(std::ceil(std::min(left_s, 3600.0) * 1000.0));
}

}  // namespace

ColumnsSensorSet::ColumnsSensorSet(std::unique_ptr<ByteLink> link, Fixture fixture,
                                   const std::vector<std::vector<NamedColumn>>& columns,
                                   const SourceOptions& options)
    : link_(std::move(link)),
      fixture_(std::move(fixture)),
      backoff_(options.reconnect_initial_s, options.reconnect_max_s),
      buffer_(kSetReadChunkBytes) {
  if (columns.size() != fixture_.sensors.size() || columns.empty()) {
    throw Error(fmt::format("--columns names {} sensors, the fixture has {}", columns.size(),
                            fixture_.sensors.size()));
  }
  // A line of 3N columns is longer than one sensor's: the garbage limit grows with it.
  const long max_line_bytes =
      options.max_line_bytes * static_cast<long>(std::max<std::size_t>(1, columns.size()));
  for (std::size_t i = 0; i < columns.size(); ++i) {
    SampleFormat format = options.format;
    format.columns = columns[i];
    lanes_.push_back(std::make_unique<Lane>(
        fmt::format("{} [{}]", link_->Describe(), fixture_.sensors[i].serial), max_line_bytes,
        format, options.gap_factor, options.dead_after_s, WallNowS()));
  }
}

ColumnsSensorSet::~ColumnsSensorSet() { link_->Close(); }

std::string ColumnsSensorSet::Describe() const {
  return fmt::format("{} ({} sensors by --columns)", link_->Describe(), lanes_.size());
}

const SourceStatus& ColumnsSensorSet::status(std::size_t sensor) const {
  return lanes_.at(sensor)->tracker.status();
}

ReadResult ColumnsSensorSet::Read(double timeout_s, SensorSetSamples* out) {
  out->Resize(lanes_.size());
  for (auto& lane : lanes_) lane->result = {};
  const double deadline_s = WallNowS() + std::max(0.0, timeout_s);
  const long before = out->total();
  for (;;) {
    if (!input_done_) Fill(deadline_s, out);
    if (out->total() > before || input_done_ || WallNowS() >= deadline_s) break;
  }
  ReadResult all;
  const double now_s = WallNowS();
  for (auto& lane : lanes_) {
    if (input_done_) lane->tracker.OnEnded(&lane->result);
    lane->tracker.Tick(now_s, &lane->result);
    MergeReadResult(lane->result, &all);
  }
  all.ended = input_done_;
  return all;
}

void ColumnsSensorSet::Fill(double deadline_s, SensorSetSamples* out) {
  if (!open_ && !TryOpen(deadline_s)) {
    if (!input_done_) source_detail::SleepS(std::min(0.01, deadline_s - WallNowS()));
    return;
  }
  pollfd p{link_->fd(), POLLIN, 0};
  const int rc = poll(&p, 1, SetPollTimeoutMs(deadline_s));
  if (rc < 0 && errno != EINTR) {
    EndOfData(std::string("poll: ") + std::strerror(errno), true, out);
  } else if (rc > 0) {
    ReadAvailable(out);
  }
}

bool ColumnsSensorSet::TryOpen(double deadline_s) {
  const double now_s = WallNowS();
  if (!backoff_.Due(now_s, deadline_s)) return false;
  std::string error;
  switch (link_->Open(std::max(0.0, deadline_s - now_s), &error)) {
    case ByteLink::OpenStep::kOpen:
      open_ = true;
      backoff_.Succeeded();
      for (auto& lane : lanes_) lane->tracker.OnLinkUp(WallNowS(), &lane->result);
      return true;
    case ByteLink::OpenStep::kPending:
      return false;
    case ByteLink::OpenStep::kFailed:
      for (auto& lane : lanes_) lane->tracker.OnOpenFailed(error);
      if (!link_->reopens()) input_done_ = true;
      backoff_.Failed(WallNowS());
      return false;
  }
  return false;
}

void ColumnsSensorSet::ReadAvailable(SensorSetSamples* out) {
  size_t taken = 0;
  while (open_ && taken < kSetMaxBytesPerCall) {
    const ssize_t n = read(link_->fd(), buffer_.data(), buffer_.size());
    if (n > 0) {
      taken += static_cast<size_t>(n);
      Feed(std::string_view(buffer_.data(), static_cast<size_t>(n)), out);
      pollfd p{link_->fd(), POLLIN, 0};
      if (poll(&p, 1, 0) <= 0) return;
    } else if (n == 0) {
      EndOfData(link_->reopens() ? "the other end closed the link" : "end of data", false, out);
    } else if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) {
      return;
    } else {
      EndOfData(std::string("read: ") + std::strerror(errno), true, out);
    }
  }
}

void ColumnsSensorSet::Feed(std::string_view bytes, SensorSetSamples* out) {
  const double now_s = WallNowS();
  for (std::size_t i = 0; i < lanes_.size(); ++i) {
    Lane& lane = *lanes_[i];
    std::vector<Sample>& dest = out->per_sensor[i];
    const std::size_t first = dest.size();
    LineStream::FeedResult fed;
    lane.lines.Feed(bytes, &dest, &fed);
    lane.tracker.OnMalformed(fed.malformed, fed.last_malformed, &lane.result);
    if (dest.size() > first)
      lane.tracker.OnSamples(dest.data() + first, static_cast<long>(dest.size() - first), now_s,
                             &lane.result);
  }
}

void ColumnsSensorSet::EndOfData(const std::string& why, bool failed, SensorSetSamples* out) {
  link_->Close();
  open_ = false;
  const std::string described = link_->Describe() + ": " + why;
  if (link_->reopens()) {
    for (auto& lane : lanes_) {
      lane->lines.DiscardPartial();
      lane->tracker.OnLinkLost(described, &lane->result);
    }
    backoff_.Failed(WallNowS());
    return;
  }
  const double now_s = WallNowS();
  for (std::size_t i = 0; i < lanes_.size(); ++i) {
    Lane& lane = *lanes_[i];
    std::vector<Sample>& dest = out->per_sensor[i];
    const std::size_t first = dest.size();
    LineStream::FeedResult fed;
    lane.lines.Finish(&dest, &fed);
    lane.tracker.OnMalformed(fed.malformed, fed.last_malformed, &lane.result);
    if (dest.size() > first)
      lane.tracker.OnSamples(dest.data() + first, static_cast<long>(dest.size() - first), now_s,
                             &lane.result);
    if (failed) lane.tracker.OnOpenFailed(described);
  }
  input_done_ = true;
}

}  // namespace accelcal
