#include "accelcal/bags/bag_open.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>

#include <fmt/format.h>

#include "accelcal/bags/mcap_file.h"
#include "accelcal/bags/ros1_bag_file.h"
#include "accelcal/bags/ros2_bag_folder.h"
#include "accelcal/bags/ros2_sqlite_file.h"
#include "accelcal/base/error.h"

namespace accelcal::bags {
namespace {

bool EndsWith(const std::string& text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::optional<BagKind> DetectBag(const std::string& path) {
  if (path.empty() || path == "-") return std::nullopt;
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return std::nullopt;
  if (S_ISDIR(info.st_mode)) {
    struct stat yaml {};
    if (::stat((path + "/metadata.yaml").c_str(), &yaml) == 0) return BagKind::kRos2Folder;
    return std::nullopt;
  }
  if (!S_ISREG(info.st_mode)) return std::nullopt;
  char head[16] = {};
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  const ssize_t got = ::read(fd, head, sizeof head);
  ::close(fd);
  if (got >= 8 && std::memcmp(head, "\x89MCAP0\r\n", 8) == 0) return BagKind::kMcap;
  if ((got >= 9 && std::memcmp(head, "#ROSBAG V", 9) == 0) ||
      (got >= 12 && std::memcmp(head, "#ROSRECORD V", 12) == 0))
    return BagKind::kRos1;  // older formats too: the ROS 1 reader refuses them by name
  if (got == 16 && std::memcmp(head, "SQLite format 3\0", 16) == 0 &&
      (EndsWith(path, ".db3") || Ros2SqliteFile::HoldsRosbag2Tables(path)))
    return BagKind::kRos2Sqlite;
  return std::nullopt;
}

std::unique_ptr<BagFile> OpenBag(const std::string& path) {
  const std::optional<BagKind> kind = DetectBag(path);
  if (!kind) throw Error(fmt::format("{}: not a bag (ROS 1 .bag, MCAP, ROS 2 .db3, or a ROS 2 bag folder)", path));
  switch (*kind) {
    case BagKind::kRos1: return std::make_unique<Ros1BagFile>(path);
    case BagKind::kMcap: return std::make_unique<McapFile>(path);
    case BagKind::kRos2Sqlite: return std::make_unique<Ros2SqliteFile>(path);
    case BagKind::kRos2Folder: return std::make_unique<Ros2BagFolder>(path);
  }
  throw Error("unreachable bag kind");
}

}  // namespace accelcal::bags
