// What `accelcal bag-info` says of a bag: every topic with its type, message count, rate, time
// span and gaps (from the bag's receive times), and for each sensor_msgs/Imu topic the same of
// its header stamps (what accelcal reads), with the stamps out of order and the messages that
// are not an Imu. One pass over the bag, a chunk at a time.
//
// Rate: 1 / the median interval of the first 1024. A gap: an interval over 1.5 median
// intervals for the header stamps (the rule `accelcal allan` counts gaps by), over 3 for the
// receive times (transport jitter: the live sources' rule).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace accelcal::bags {

// The intervals of one stream of times: median, gaps, order.
struct TimeStats {
  long long count = 0;
  double first_s = 0.0;
  double last_s = 0.0;
  double median_interval_s = 0.0;  // 0 before two
  long long gaps = 0;
  double largest_gap_s = 0.0;
  double largest_gap_at_s = 0.0;  // the time before it
  long long out_of_order = 0;     // times not after the one before
};

struct TopicInfo {
  std::string name;
  std::string type;
  bool imu = false;
  TimeStats receive;
  // sensor_msgs/Imu topics: their header stamps, and the messages that could not be decoded
  // (with the first one's reason).
  TimeStats stamps;
  long long undecodable = 0;
  std::string undecodable_why;
};

struct BagInfo {
  std::string path;
  std::string description;  // "MCAP file, zstd chunks"
  std::vector<TopicInfo> topics;
  std::vector<std::string> notes;  // what was read around (a cut file)
};

// Reads the whole bag at `path`. Throws accelcal::Error when it cannot be read.
BagInfo DescribeBag(const std::string& path);

}  // namespace accelcal::bags
