// The file: source of a ROS bag (file:imu.mcap, file:rosbag2_dir): its IMU topic's samples
// (bags/bag_sample_stream.h: the topic of SourceOptions::format.bag, the same time checks),
// delivered as a recording's are, as fast as they are read or paced by t (--realtime), then
// ended. Damage found part way (a message that is not an Imu, a chunk whose CRC does not match)
// ends the source with the reason in status().link_error; the samples before it were delivered.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accelcal/acquire/source/sample_source.h"
#include "accelcal/acquire/source/source_options.h"
#include "accelcal/acquire/source/status_tracker.h"
#include "accelcal/bags/bag_sample_stream.h"

namespace accelcal {

class BagSource final : public SampleSource {
 public:
  // Opens the bag and chooses its topic now: throws accelcal::Error as BagSampleStream does.
  BagSource(const std::string& path, const SourceOptions& options);

  std::string Describe() const override { return "file:" + path_; }
  ReadResult Read(double timeout_s, std::vector<Sample>* out) override;
  const SourceStatus& status() const override { return tracker_.status(); }
  std::string DescribeReading() const override { return stream_.Summary().Describe(); }

 private:
  void Pull();
  size_t Due(double now_s) const;  // pending samples due by now (all when not paced)

  std::string path_;
  bool realtime_;
  bags::BagSampleStream stream_;
  StatusTracker tracker_;
  std::vector<Sample> pending_;
  size_t next_ = 0;
  bool up_ = false;
  bool input_done_ = false;
  double pace_origin_wall_s_;
  double pace_origin_t_s_;
};

}  // namespace accelcal
