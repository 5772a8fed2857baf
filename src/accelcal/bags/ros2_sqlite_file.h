// ROS 2 bags in SQLite (.db3: rosbag2's default storage before Iron), read with the schema
// rosbag2's sqlite3 plugin writes: topics(id, name, type, serialization_format, ...) and
// messages(id, topic_id, timestamp, data), timestamp the receive time in ns, data the
// serialized message (CDR with its encapsulation header); from Jazzy on, message_definitions
// holds each type's definition.
//
// Messages are read in the table's order (the order they were written: rosbag2 writes as they
// arrive), in batches: from the file's pages directly (sqlite_row_pages.h: a third of SQLite's
// cost per row) while the table is the shape rosbag2 writes, through SQLite for the rest (from
// the first thing the page reader does not read on, or all of it). Opened read-only: nothing is
// ever written to the bag. A database damaged part way (a recorder killed mid-write) is read up
// to its last readable row, and Notes() says so.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "accelcal/bags/bag_file.h"
#include "accelcal/bags/mapped_file.h"
#include "accelcal/bags/sqlite_row_pages.h"

struct sqlite3;
struct sqlite3_stmt;

namespace accelcal::bags {

class Ros2SqliteFile final : public BagFile {
 public:
  // Throws accelcal::Error when the file cannot be opened or holds no rosbag2 tables.
  explicit Ros2SqliteFile(const std::string& path);
  ~Ros2SqliteFile() override;
  Ros2SqliteFile(const Ros2SqliteFile&) = delete;
  Ros2SqliteFile& operator=(const Ros2SqliteFile&) = delete;

  std::string Description() const override { return "ROS 2 bag (SQLite)"; }
  std::optional<std::vector<TopicSummary>> IndexedTopics(bool with_counts) override;
  bool ReadBatch(MessageSink* sink) override;
  std::vector<std::string> Notes() const override { return notes_; }

  // True when `path` is an SQLite file holding rosbag2's topics and messages tables.
  static bool HoldsRosbag2Tables(const std::string& path);

 private:
  struct Topic {
    int64_t id = 0;
    BagConnection connection;
    int slot = -2;
  };
  void ReadTopics();
  void StartReading(MessageSink* sink);
  bool StartReadingPages();
  // The statement over the wanted rows, those after `after_rowid` when given.
  void PrepareRows(std::optional<int64_t> after_rowid);
  int SlotOf(int64_t topic_id) const;
  [[noreturn]] void Fail(const std::string& what) const;

  std::string path_;
  sqlite3* db_ = nullptr;
  sqlite3_stmt* rows_ = nullptr;
  std::vector<int64_t> wanted_ids_;
  std::unique_ptr<MappedFile> mapped_;    // while the pages are read directly
  std::optional<SqliteRowPages> pages_;
  std::vector<Topic> topics_;
  bool has_definitions_ = false;  // Jazzy's message_definitions table
  bool started_ = false;
  bool done_ = false;
  long long rows_read_ = 0;
  std::vector<std::string> notes_;
};

}  // namespace accelcal::bags
