#include "accelcal/bags/bag_topics.h"

#include <algorithm>

#include <fmt/format.h>

#include "accelcal/bags/bag_open.h"
#include "accelcal/bags/imu_message.h"
#include "accelcal/base/error.h"
#include "accelcal/base/text_scan.h"

namespace accelcal::bags {
namespace {

std::string Shown(const std::string& name) { return detail::PrintableExcerpt(name, 80); }

std::vector<TopicSummary> ImuTopicsOf(const std::vector<TopicSummary>& topics) {
  std::vector<TopicSummary> imu;
  for (const TopicSummary& t : topics)
    if (IsImuType(t.type)) imu.push_back(t);
  return imu;
}

const TopicSummary* Find(const std::vector<TopicSummary>& topics, const std::string& name) {
  const auto it = std::find_if(topics.begin(), topics.end(),
                               [&](const TopicSummary& t) { return t.name == name; });
  return it == topics.end() ? nullptr : &*it;
}

// The listing with counts: the index's when it has them, else from a pass.
std::vector<TopicSummary> CountedTopics(const std::string& path, BagFile& file) {
  std::optional<std::vector<TopicSummary>> topics = file.IndexedTopics(true);
  if (topics && std::all_of(topics->begin(), topics->end(),
                            [](const TopicSummary& t) { return t.messages >= 0; }))
    return *topics;
  return ListTopics(path);
}

}  // namespace

int TopicTally::Wants(const BagConnection& connection) {
  const auto it = std::find_if(topics_.begin(), topics_.end(),
                               [&](const TopicSummary& t) { return t.name == connection.topic; });
  if (it != topics_.end()) return static_cast<int>(it - topics_.begin());
  topics_.push_back({connection.topic, connection.type, 0, 0, 0});
  return static_cast<int>(topics_.size() - 1);
}

void TopicTally::OnMessage(int slot, uint64_t receive_time_ns, const uint8_t*, size_t) {
  TopicSummary& t = topics_[static_cast<size_t>(slot)];
  if (t.messages++ == 0 || receive_time_ns < t.first_ns) t.first_ns = receive_time_ns;
  t.last_ns = std::max(t.last_ns, receive_time_ns);
}

std::vector<TopicSummary> ListTopics(const std::string& path) {
  const std::unique_ptr<BagFile> file = OpenBag(path);
  std::optional<std::vector<TopicSummary>> indexed = file->IndexedTopics(true);
  if (indexed && std::all_of(indexed->begin(), indexed->end(),
                             [](const TopicSummary& t) { return t.messages >= 0; }))
    return *indexed;
  TopicTally tally;
  while (file->ReadBatch(&tally)) {
  }
  return tally.topics();
}

std::string DescribeTopic(const TopicSummary& t) {
  std::string out = fmt::format("{} ({}", Shown(t.name), t.type.empty() ? "no type" : Shown(t.type));
  if (t.messages >= 0) out += fmt::format(", {} message{}", t.messages, t.messages == 1 ? "" : "s");
  if (t.messages >= 2 && t.last_ns > t.first_ns) {
    const double rate = static_cast<double>(t.messages - 1) / (static_cast<double>(t.last_ns - t.first_ns) * 1e-9);
    out += fmt::format(", {:.4g} Hz", rate);
  }
  return out + ")";
}

std::string DescribeTopics(const std::vector<TopicSummary>& topics) {
  if (topics.empty()) return "none";
  std::string out;
  for (const TopicSummary& t : topics) out += (out.empty() ? "" : ", ") + DescribeTopic(t);
  return out;
}

std::string NoMessagesOn(const std::string& path, const std::string& topic,
                         const std::vector<TopicSummary>& topics) {
  return fmt::format("{}: 0 messages on topic {}: the topics are {}", path, Shown(topic),
                     DescribeTopics(topics));
}

TopicChoice ChooseImuTopic(const std::string& path, BagFile& file, const std::string& requested,
                           bool* scanned) {
  *scanned = false;
  std::optional<std::vector<TopicSummary>> listed = file.IndexedTopics(false);
  if (!requested.empty()) {
    if (!listed) return {requested, "", -1};  // no index: the reading tells
    const TopicSummary* t = Find(*listed, requested);
    if (t == nullptr || t->messages == 0)
      throw Error(NoMessagesOn(path, requested, CountedTopics(path, file)));
    if (!IsImuType(t->type)) {
      const std::vector<TopicSummary> imu = ImuTopicsOf(CountedTopics(path, file));
      throw Error(fmt::format("{}: topic {} holds {} messages, not sensor_msgs/Imu; {}", path,
                              Shown(requested), t->type.empty() ? "untyped" : Shown(t->type),
                              imu.empty() ? "the bag has no IMU topic"
                                          : fmt::format("its IMU topic{}: {}", imu.size() == 1 ? "" : "s",
                                                        DescribeTopics(imu))));
    }
    return {t->name, t->type, t->messages};
  }
  std::vector<TopicSummary> topics;
  if (listed) {
    topics = *listed;
  } else {
    topics = ListTopics(path);
    *scanned = true;
  }
  const auto candidates = [](const std::vector<TopicSummary>& all) {
    std::vector<TopicSummary> imu = ImuTopicsOf(all);
    // Topics known to be empty are not candidates.
    imu.erase(std::remove_if(imu.begin(), imu.end(), [](const TopicSummary& t) { return t.messages == 0; }),
              imu.end());
    return imu;
  };
  std::vector<TopicSummary> imu = candidates(topics);
  if (imu.size() == 1) return {imu.front().name, imu.front().type, imu.front().messages};
  // Not one: the counts decide (an IMU topic without messages is none), and the refusal lists them.
  const std::vector<TopicSummary> counted = *scanned ? topics : CountedTopics(path, file);
  imu = candidates(counted);
  if (imu.size() == 1) return {imu.front().name, imu.front().type, imu.front().messages};
  if (imu.empty())
    throw Error(fmt::format("{} holds no sensor_msgs/Imu messages: its topics are {}", path,
                            DescribeTopics(counted)));
  throw Error(fmt::format("{} holds {} IMU topics: {}: give the one to read with --topic NAME",
                          path, imu.size(), DescribeTopics(imu)));
}

}  // namespace accelcal::bags
