// The rows of rosbag2's messages table read straight from the SQLite file's pages, by the file
// format SQLite documents and keeps stable (sqlite.org/fileformat2.html: the database header,
// table b-tree pages, cells, overflow chains, the record format), instead of through SQLite's
// statement machine: a table scan through sqlite3_step costs ~185 ns a row on this project's
// machine where walking the pages costs ~55 (bench/README.md, "Bags"), and that difference is
// what puts a .db3 under or over the text reader's speed.
//
// It reads one shape only: a rowid table whose rows are (id INTEGER PRIMARY KEY, topic_id
// integer, timestamp integer, data blob), rows in rowid order (ORDER BY id), the rows of the
// wanted topic ids. Anything else it meets (a page type, a pointer out of the file, a cell out
// of its page, a rowid not increasing, a value of another type, a row of other columns) stops
// it where it is: stopped() says so and last_rowid() is the last row it read whole, and the
// caller goes on through SQLite from there (`WHERE id > last_rowid`), which reads what it can
// and names the damage in its own words. It never delivers a row SQLite would not.
//
// The caller holds an SQLite read transaction on the same file meanwhile (so no writer can
// change the pages under it) and keeps it away from WAL databases whose log holds pages.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "accelcal/bags/mapped_file.h"

namespace accelcal::bags {

class SqliteRowPages {
 public:
  struct Row {
    int64_t rowid = 0;
    int64_t topic_id = 0;
    int64_t timestamp = 0;
    const uint8_t* data = nullptr;  // valid until the next call of Next
    size_t size = 0;
  };

  // The database header of `file` read; nullopt when it is not one this reads (not an SQLite
  // file, a page size out of range, a file format version above 2).
  static std::optional<SqliteRowPages> Open(MappedFile* file, uint32_t root_page,
                                            std::vector<int64_t> wanted_topic_ids);

  // The next row of a wanted topic, in rowid order; false at the table's end or where it
  // stopped (stopped()).
  bool Next(Row* row);
  bool stopped() const { return stopped_; }
  // The rowid of the last row read whole (of any topic); read_any() false: none.
  int64_t last_rowid() const { return last_rowid_; }
  bool read_any() const { return read_any_; }
  // The format's file format read version (1 rollback journal, 2 WAL).
  int read_version() const { return read_version_; }

 private:
  struct Frame {
    const uint8_t* page = nullptr;
    const uint8_t* header = nullptr;  // the b-tree page header
    uint32_t cells = 0;
    uint32_t next = 0;  // the next cell (an interior page: cells is its right-most child)
    bool leaf = false;
  };

  SqliteRowPages(MappedFile* file, uint32_t root_page, std::vector<int64_t> wanted);
  bool Push(uint32_t page_number);
  // One leaf cell: true with *row when it is a wanted row; false otherwise (*skip true: a row
  // of another topic, read whole; false: stopped).
  bool ReadCell(const Frame& leaf, uint32_t cell, Row* row, bool* skip);
  bool Assemble(const uint8_t* local_bytes, size_t local, uint64_t payload_bytes,
                uint32_t first_overflow, const uint8_t** payload);
  bool Stop();

  MappedFile* file_;
  uint32_t root_page_;
  std::vector<int64_t> wanted_;
  size_t page_bytes_ = 0;
  size_t usable_bytes_ = 0;
  uint32_t pages_ = 0;  // whole pages in the file
  int read_version_ = 0;
  std::vector<Frame> stack_;
  std::vector<std::vector<uint8_t>> interior_copies_;  // by depth
  std::vector<uint8_t> assembled_;  // a payload that runs onto overflow pages
  bool started_ = false;
  bool stopped_ = false;
  bool read_any_ = false;
  int64_t last_rowid_ = 0;
};

}  // namespace accelcal::bags
