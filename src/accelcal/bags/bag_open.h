// Which bag a path is, and opening it: a ROS 2 bag folder (its metadata.yaml), an MCAP file,
// a ROS 1 bag, or a ROS 2 SQLite file (.db3, or any SQLite file holding rosbag2's tables),
// told by their first bytes, not their names. Anything else (a text recording, a pipe, an
// accelcal session) is not a bag.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "accelcal/bags/bag_file.h"

namespace accelcal::bags {

enum class BagKind { kRos1, kMcap, kRos2Sqlite, kRos2Folder };

// The kind of bag at `path`, or nullopt when it is not one (or cannot be read: the reader that
// opens it then says why). Never reads from a pipe or a device ("-" is standard input).
std::optional<BagKind> DetectBag(const std::string& path);

// Opens the bag at `path`. Throws accelcal::Error when it cannot be opened or is not a bag.
std::unique_ptr<BagFile> OpenBag(const std::string& path);

}  // namespace accelcal::bags
