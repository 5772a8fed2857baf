// One interface over the bag formats (ROS 1 .bag, MCAP, ROS 2 SQLite .db3, a ROS 2 bag folder):
// what a file says about its topics, and its messages handed over in file order, one chunk (or
// batch) at a time, so that memory stays bounded.
//
// A connection is one publisher's stream on a topic (a ROS 1 connection, an MCAP channel, a
// ROS 2 SQLite topic row): a topic may have several. Times are the bag's receive times (MCAP
// log_time, the ROS 1 record time, the ROS 2 SQLite timestamp), ns since the epoch the
// recorder used.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace accelcal::bags {

struct BagConnection {
  std::string topic;
  std::string type;             // as the bag names it: "sensor_msgs/msg/Imu", "sensor_msgs/Imu"
  std::string encoding;         // "cdr", "ros1", or what the file names
  std::string schema_encoding;  // "ros2msg", "ros2idl", "ros1msg"; empty: the file holds none
  std::string schema;           // the message definition, when the file holds one
  std::string md5sum;           // ROS 1: the definition's MD5
};

// A topic as a file's index or summary lists it, before any message is read.
struct TopicSummary {
  std::string name;
  std::string type;
  long long messages = -1;  // -1: not known without reading
  uint64_t first_ns = 0;    // receive times of its first and last messages; both 0: unknown
  uint64_t last_ns = 0;
};

// Receives the messages of the connections it wants.
class MessageSink {
 public:
  virtual ~MessageSink() = default;
  // A connection met for the first time, before its first message: the slot its messages are
  // handed over with (>= 0), or -1 for none of them.
  virtual int Wants(const BagConnection& connection) = 0;
  // One message (its bytes valid during the call only).
  virtual void OnMessage(int slot, uint64_t receive_time_ns, const uint8_t* data, size_t size) = 0;
};

class BagFile {
 public:
  virtual ~BagFile() = default;

  // "ROS 1 bag", "MCAP", "ROS 2 bag (SQLite)", with its compression when it has one.
  virtual std::string Description() const = 0;
  // The topics its index or summary lists; nullopt when it has none (a cut file, a file not
  // closed by its writer): then only reading it tells. `with_counts` false: message counts may
  // stay unknown where they cost a pass to know (SQLite).
  virtual std::optional<std::vector<TopicSummary>> IndexedTopics(bool with_counts) = 0;
  // Reads on by one chunk (or batch), handing each message of a wanted connection to `sink` in
  // file order. False once the file is exhausted. Throws accelcal::Error for damage it cannot
  // read past (a chunk whose CRC does not match, a record that contradicts the format), naming
  // the file and where.
  virtual bool ReadBatch(MessageSink* sink) = 0;
  // Damage read around, in words, for the reading's summary: "cut short inside chunk 12 (at
  // byte 1234567 of its 2000000): read up to its last whole message".
  virtual std::vector<std::string> Notes() const = 0;
};

}  // namespace accelcal::bags
