// A bag's topics in words, and the choice of the IMU topic to read: the one the user named
// (--topic), or the only one the bag holds. Every refusal lists what the bag does hold:
//   imu.bag: 0 messages on topic /imu: the topics are /imu/data (sensor_msgs/Imu, 12000
//     messages, 200 Hz), /tf (tf2_msgs/TFMessage, 600 messages, 10 Hz)
//   imu.mcap: topic /tf holds tf2_msgs/msg/TFMessage messages, not sensor_msgs/Imu; its IMU
//     topic: /imu (sensor_msgs/msg/Imu, 12000 messages, 200 Hz)
//   imu.db3 holds 2 IMU topics: /imu/left (...), /imu/right (...): give the one to read with
//     --topic NAME
#pragma once

#include <map>
#include <string>
#include <vector>

#include "accelcal/bags/bag_file.h"

namespace accelcal::bags {

// Counts every message of a bag by topic (its first and last receive times too): the topic
// list of a bag without an index.
class TopicTally final : public MessageSink {
 public:
  int Wants(const BagConnection& connection) override;
  void OnMessage(int slot, uint64_t receive_time_ns, const uint8_t* data, size_t size) override;
  const std::vector<TopicSummary>& topics() const { return topics_; }

 private:
  std::vector<TopicSummary> topics_;
};

// The topics of the bag at `path`: its index's (with counts), or, without one, from a pass over
// all its messages.
std::vector<TopicSummary> ListTopics(const std::string& path);

// "/imu (sensor_msgs/msg/Imu, 12000 messages, 200 Hz)": the rate from the count and the span,
// when both are known.
std::string DescribeTopic(const TopicSummary& topic);
// The topics described, comma-separated; "none" for no topic.
std::string DescribeTopics(const std::vector<TopicSummary>& topics);

struct TopicChoice {
  std::string topic;
  std::string type;
  long long messages = -1;  // -1: not known before reading
};

// The IMU topic of the bag at `path` (opened as `file`) to read: `requested` when given (a
// topic the index does not list, or that holds other messages or none, refused with the
// list); else the only sensor_msgs/Imu topic with messages. A bag without an index is read
// once for its topics when no topic is requested (`*scanned` true). Throws accelcal::Error.
TopicChoice ChooseImuTopic(const std::string& path, BagFile& file, const std::string& requested,
                           bool* scanned);

// The error for a topic that gave no message (an unindexed bag, found at the end of its
// reading): "PATH: 0 messages on topic X: the topics are ...".
std::string NoMessagesOn(const std::string& path, const std::string& topic,
                         const std::vector<TopicSummary>& topics);

}  // namespace accelcal::bags
