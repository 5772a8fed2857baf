#include "accelcal/bags/bag_info.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "accelcal/bags/bag_file.h"
#include "accelcal/bags/bag_open.h"
#include "accelcal/bags/imu_message.h"

namespace accelcal::bags {
namespace {

constexpr size_t kMedianIntervals = 1024;

// Accumulates TimeStats; the first kMedianIntervals intervals are held until the median is
// known, then every interval is judged as it comes.
class TimeTally {
 public:
  explicit TimeTally(double gap_factor) : gap_factor_(gap_factor) {}

  void Add(double t_s) {
    if (s_.count++ == 0) {
      s_.first_s = s_.last_s = previous_ = t_s;
      return;
    }
    const double dt = t_s - previous_;
    previous_ = t_s;
    s_.last_s = std::max(s_.last_s, t_s);
    if (!(dt > 0.0)) {
      ++s_.out_of_order;
      return;
    }
    if (held_.size() < kMedianIntervals) {
      held_.push_back({t_s - dt, dt});
      if (held_.size() == kMedianIntervals) Settle();
      return;
    }
    Judge(t_s - dt, dt);
  }

  TimeStats Result() {
    if (!settled_ && !held_.empty()) Settle();
    return s_;
  }

 private:
  struct Interval {
    double before_s;
    double dt_s;
  };
  void Settle() {
    std::vector<double> v;
    for (const Interval& i : held_) v.push_back(i.dt_s);
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    s_.median_interval_s = v[v.size() / 2];
    settled_ = true;
    for (const Interval& i : held_) Judge(i.before_s, i.dt_s);
    held_.clear();
    held_.shrink_to_fit();
  }
  void Judge(double before_s, double dt_s) {
    if (dt_s <= gap_factor_ * s_.median_interval_s) return;
    ++s_.gaps;
    if (dt_s > s_.largest_gap_s) {
      s_.largest_gap_s = dt_s;
      s_.largest_gap_at_s = before_s;
    }
  }

  double gap_factor_;
  TimeStats s_;
  double previous_ = 0.0;
  std::vector<Interval> held_;
  bool settled_ = false;
};

double Seconds(uint64_t ns) {
  return static_cast<double>(ns / 1000000000u) + static_cast<double>(ns % 1000000000u) * 1e-9;
}

class InfoSink final : public MessageSink {
 public:
  int Wants(const BagConnection& c) override {
    auto it = std::find_if(topics_.begin(), topics_.end(), [&](const Topic& t) { return t.info.name == c.topic; });
    if (it == topics_.end()) {
      topics_.push_back(Topic{});
      it = topics_.end() - 1;
      it->info.name = c.topic;
      it->info.type = c.type;
      it->info.imu = IsImuType(c.type);
    }
    Topic& t = *it;
    const int topic = static_cast<int>(it - topics_.begin());
    std::string why;
    ImuEncoding encoding = ImuEncoding::kCdr;
    bool decodable = t.info.imu && ImuEncodingOf(c, &encoding, &why);
    if (decodable) why = ImuSchemaMismatch(c, encoding);
    if (t.info.imu && !why.empty() && t.info.undecodable_why.empty()) t.info.undecodable_why = why;
    decodable = decodable && why.empty();
    slots_.push_back({topic, decodable, encoding});
    return static_cast<int>(slots_.size() - 1);
  }

  void OnMessage(int slot, uint64_t receive_time_ns, const uint8_t* data, size_t size) override {
    const Slot& s = slots_[static_cast<size_t>(slot)];
    Topic& t = topics_[static_cast<size_t>(s.topic)];
    t.receive.Add(Seconds(receive_time_ns));
    if (!t.info.imu) return;
    ImuReading r;
    std::string why;
    if (!s.decodable || !DecodeImu(s.encoding, data, size, &r, &why)) {
      if (t.info.undecodable++ == 0 && !why.empty()) t.info.undecodable_why = why;
      return;
    }
    t.stamps.Add(static_cast<double>(r.stamp_sec) + static_cast<double>(r.stamp_nsec) * 1e-9);
  }

  std::vector<TopicInfo> Result() {
    std::vector<TopicInfo> out;
    for (Topic& t : topics_) {
      t.info.receive = t.receive.Result();
      if (t.info.imu) t.info.stamps = t.stamps.Result();
      out.push_back(t.info);
    }
    return out;
  }

 private:
  struct Topic {
    TopicInfo info;
    TimeTally receive{3.0};
    TimeTally stamps{1.5};
  };
  struct Slot {
    int topic;
    bool decodable;
    ImuEncoding encoding;
  };
  std::vector<Topic> topics_;
  std::vector<Slot> slots_;
};

}  // namespace

BagInfo DescribeBag(const std::string& path) {
  const std::unique_ptr<BagFile> file = OpenBag(path);
  InfoSink sink;
  while (file->ReadBatch(&sink)) {
  }
  BagInfo info;
  info.path = path;
  info.description = file->Description();
  info.topics = sink.Result();
  info.notes = file->Notes();
  // Topics the index lists without a message are topics too.
  if (const auto indexed = file->IndexedTopics(false)) {
    for (const TopicSummary& t : *indexed) {
      if (std::none_of(info.topics.begin(), info.topics.end(), [&](const TopicInfo& i) { return i.name == t.name; })) {
        TopicInfo empty;
        empty.name = t.name;
        empty.type = t.type;
        empty.imu = IsImuType(t.type);
        info.topics.push_back(empty);
      }
    }
  }
  return info;
}

}  // namespace accelcal::bags
