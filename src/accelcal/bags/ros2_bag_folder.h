// A ROS 2 bag folder: metadata.yaml beside its storage files (rosbag2's layout: `ros2 bag record`
// writes NAME/metadata.yaml and NAME/NAME_0.db3 or NAME_0.mcap, split bags more files).
//
// Of metadata.yaml only what finding the files takes is read (no YAML library: rosbag2 writes
// these few keys as plain scalars and a plain list): storage_identifier (sqlite3 or mcap),
// relative_file_paths (the files, in order), compression_format and compression_mode. The topics,
// types and counts come from the files themselves. A bag whose files or messages rosbag2
// compressed whole (compression_mode FILE or MESSAGE) is refused with what to do.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accelcal/bags/bag_file.h"

namespace accelcal::bags {

struct Ros2BagMetadata {
  std::string storage_identifier;  // "sqlite3", "mcap"
  std::vector<std::string> relative_file_paths;
  std::string compression_format;  // "" or "zstd"
  std::string compression_mode;    // "", "NONE", "FILE", "MESSAGE"
};

// Reads the keys above from metadata.yaml's text; `source` names it in errors. Throws
// accelcal::Error when a key that must be there is not.
Ros2BagMetadata ParseRos2BagMetadata(const std::string& text, const std::string& source);

// The files of a bag folder, read one after another as one bag.
class Ros2BagFolder final : public BagFile {
 public:
  // Throws accelcal::Error when metadata.yaml cannot be read, names a storage this reader does
  // not know, or a file that is not there.
  explicit Ros2BagFolder(const std::string& folder);

  std::string Description() const override;
  std::optional<std::vector<TopicSummary>> IndexedTopics(bool with_counts) override;
  bool ReadBatch(MessageSink* sink) override;
  std::vector<std::string> Notes() const override;

 private:
  std::string folder_;
  Ros2BagMetadata metadata_;
  std::vector<std::unique_ptr<BagFile>> files_;
  size_t current_ = 0;
};

}  // namespace accelcal::bags
