#include "accelcal/acquire/source/columns_sensor_set.h"

#include <algorithm>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/acquire/source/wall_clock.h"

namespace accelcal {
namespace {

using source_detail::WallNowS;

}  // namespace

ColumnsSensorSet::ColumnsSensorSet(std::unique_ptr<ByteLink> link, Fixture fixture,
                                   const std::vector<std::vector<NamedColumn>>& columns,
                                   const SourceOptions& options)
    : reader_(std::move(link), options), fixture_(std::move(fixture)) {
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
        fmt::format("{} [{}]", reader_.Describe(), fixture_.sensors[i].serial), max_line_bytes,
        format, options.gap_factor, options.dead_after_s, WallNowS()));
  }
}

ColumnsSensorSet::~ColumnsSensorSet() = default;

std::string ColumnsSensorSet::Describe() const {
  return fmt::format("{} ({} sensors by --columns)", reader_.Describe(), lanes_.size());
}

const SourceStatus& ColumnsSensorSet::status(std::size_t sensor) const {
  return lanes_.at(sensor)->tracker.status();
}

ReadResult ColumnsSensorSet::Read(double timeout_s, SensorSetSamples* out) {
  out->Resize(lanes_.size());
  for (auto& lane : lanes_) lane->result = {};
  const double deadline_s = WallNowS() + std::max(0.0, timeout_s);
  const long before = out->total();
  out_ = out;
  for (;;) {
    if (!reader_.input_done() && !reader_.Fill(deadline_s, *this) && !reader_.input_done())
      source_detail::SleepS(std::min(0.01, deadline_s - WallNowS()));  // not open: back-off
    if (out->total() > before || reader_.input_done() || WallNowS() >= deadline_s) break;
  }
  out_ = nullptr;
  ReadResult all;
  const double now_s = WallNowS();
  for (auto& lane : lanes_) {
    if (reader_.input_done()) lane->tracker.OnEnded(&lane->result);
    lane->tracker.Tick(now_s, &lane->result);
    MergeReadResult(lane->result, &all);
  }
  all.ended = reader_.input_done();
  return all;
}

void ColumnsSensorSet::OnLinkOpen() {
  for (auto& lane : lanes_) lane->tracker.OnLinkUp(WallNowS(), &lane->result);
}

void ColumnsSensorSet::OnLinkOpenFailed(const std::string& error) {
  for (auto& lane : lanes_) lane->tracker.OnOpenFailed(error);
}

void ColumnsSensorSet::Counted(std::size_t i, std::size_t first, double now_s) {
  Lane& lane = *lanes_[i];
  const std::vector<Sample>& dest = out_->per_sensor[i];
  if (dest.size() > first)
    lane.tracker.OnSamples(dest.data() + first, static_cast<long>(dest.size() - first), now_s, &lane.result);
}

// Each lane's lines by `parse` (what it fed, its malformed ones), into that sensor's samples,
// counted at one wall time.
void ColumnsSensorSet::ParseLanes(
    const std::function<void(Lane&, std::vector<Sample>*, LineStream::FeedResult*)>& parse) {
  if (out_ == nullptr) out_ = &scratch_;
  out_->Resize(lanes_.size());
  const double now_s = WallNowS();
  for (std::size_t i = 0; i < lanes_.size(); ++i) {
    Lane& lane = *lanes_[i];
    const std::size_t first = out_->per_sensor[i].size();
    LineStream::FeedResult fed;
    parse(lane, &out_->per_sensor[i], &fed);
    lane.tracker.OnMalformed(fed.malformed, fed.last_malformed, &lane.result);
    Counted(i, first, now_s);
  }
}

void ColumnsSensorSet::OnBytes(std::string_view bytes) {
  ParseLanes([bytes](Lane& lane, std::vector<Sample>* out, LineStream::FeedResult* fed) {
    lane.lines.Feed(bytes, out, fed);
  });
}

// A link that reopens loses every sensor's unterminated last line; a finished one's still count.
void ColumnsSensorSet::OnLinkEnd(const std::string& described, bool failed, bool reopens) {
  if (reopens) {
    for (auto& lane : lanes_) {
      lane->lines.DiscardPartial();
      lane->tracker.OnLinkLost(described, &lane->result);
    }
    return;
  }
  ParseLanes([](Lane& lane, std::vector<Sample>* out, LineStream::FeedResult* fed) {
    lane.lines.Finish(out, fed);
  });
  if (failed)
    for (auto& lane : lanes_) lane->tracker.OnOpenFailed(described);
}

}  // namespace accelcal
