// The messages table read from its pages (bags/sqlite_row_pages.h) against SQLite reading the
// same file: databases written here by SQLite itself (the implementation of the file format),
// in the shapes that exercise the format: deep trees of small pages, payloads on overflow
// pages, reserved bytes at the end of each page, deleted rows (free pages, gaps in the rowids),
// a WAL whose log still holds rows, and what the page reader does not read (a value of another
// type, a zeroed page), after which SQLite reads on.
#include <sqlite3.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/bags/mapped_file.h"
#include "accelcal/bags/ros2_sqlite_file.h"
#include "accelcal/bags/sqlite_row_pages.h"

namespace accelcal::bags {
namespace sqlite_row_pages_test {
namespace {

using Row = std::tuple<int64_t, int64_t, int64_t, std::vector<uint8_t>>;  // rowid, topic, time, data

void Exec(sqlite3* db, const std::string& sql) {
  char* error = nullptr;
  ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error), SQLITE_OK) << (error ? error : "") << " in " << sql;
}

// A payload of `size` bytes that differs from row to row.
std::vector<uint8_t> Payload(int64_t row, size_t size) {
  std::vector<uint8_t> out(size);
  for (size_t i = 0; i < size; ++i) out[i] = static_cast<uint8_t>(row * 31 + static_cast<int64_t>(i) * 7);
  return out;
}

struct Shape {
  int page_bytes = 4096;
  int reserved_bytes = 0;
  int rows = 2000;
  bool wal = false;
};

// A database with rosbag2's tables (as tests/e2e/lib/bags/write_bags.mjs creates them), written
// by SQLite: rows on topics 1, 2, 3 in turn, payloads of 0 to ~3 page sizes, stamps increasing.
// The connection is returned open (the caller closes it: a WAL database keeps its log while it
// is open).
sqlite3* WriteDatabase(const std::string& path, const Shape& shape) {
  std::remove(path.c_str());
  std::remove((path + "-wal").c_str());
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  if (shape.reserved_bytes > 0) {
    int reserved = shape.reserved_bytes;
    EXPECT_EQ(sqlite3_file_control(db, "main", SQLITE_FCNTL_RESERVE_BYTES, &reserved), SQLITE_OK);
  }
  Exec(db, "PRAGMA page_size = " + std::to_string(shape.page_bytes));
  if (shape.wal) Exec(db, "PRAGMA journal_mode = WAL; PRAGMA wal_autocheckpoint = 0");
  Exec(db, "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
           "serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL)");
  Exec(db, "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, "
           "timestamp INTEGER NOT NULL, data BLOB NOT NULL)");
  Exec(db, "CREATE INDEX timestamp_idx ON messages (timestamp ASC)");
  Exec(db, "INSERT INTO topics(name, type, serialization_format, offered_qos_profiles) VALUES "
           "('/a', 'sensor_msgs/msg/Imu', 'cdr', ''), ('/b', 'std_msgs/msg/String', 'cdr', ''), "
           "('/c', 'sensor_msgs/msg/Imu', 'cdr', '')");
  Exec(db, "BEGIN");
  sqlite3_stmt* insert = nullptr;
  sqlite3_prepare_v2(db, "INSERT INTO messages(topic_id, timestamp, data) VALUES (?, ?, ?)", -1, &insert, nullptr);
  for (int64_t i = 1; i <= shape.rows; ++i) {
    // Mostly short rows, every 13th long enough to run onto overflow pages (3 pages' worth).
    const size_t size = i % 13 == 0 ? static_cast<size_t>(shape.page_bytes) * 3 + static_cast<size_t>(i % 97)
                                     : static_cast<size_t>(i % 400);
    const std::vector<uint8_t> data = Payload(i, size);
    sqlite3_bind_int64(insert, 1, 1 + i % 3);
    // Stamps from 1 ns to beyond 2^32 s in ns: every integer width of the record format.
    sqlite3_bind_int64(insert, 2, i < 50 ? i * 3 : int64_t{1700000000000000000} + i * 1000000);
    static const uint8_t kNone = 0;  // a null pointer would bind NULL, not an empty blob
    sqlite3_bind_blob(insert, 3, data.empty() ? &kNone : data.data(), static_cast<int>(data.size()), SQLITE_TRANSIENT);
    EXPECT_EQ(sqlite3_step(insert), SQLITE_DONE);
    sqlite3_reset(insert);
  }
  sqlite3_finalize(insert);
  Exec(db, "COMMIT");
  return db;
}

std::vector<Row> RowsBySqlite(const std::string& path, const std::string& topics) {
  sqlite3* db = nullptr;
  sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr);
  sqlite3_stmt* s = nullptr;
  sqlite3_prepare_v2(db, ("SELECT id, topic_id, timestamp, data FROM messages WHERE topic_id IN (" + topics +
                          ") ORDER BY id").c_str(), -1, &s, nullptr);
  std::vector<Row> rows;
  while (sqlite3_step(s) == SQLITE_ROW) {
    const auto* data = static_cast<const uint8_t*>(sqlite3_column_blob(s, 3));
    const int size = sqlite3_column_bytes(s, 3);
    rows.emplace_back(sqlite3_column_int64(s, 0), sqlite3_column_int64(s, 1), sqlite3_column_int64(s, 2),
                      std::vector<uint8_t>(data, data + size));
  }
  sqlite3_finalize(s);
  sqlite3_close(db);
  return rows;
}

uint32_t RootPage(const std::string& path) {
  sqlite3* db = nullptr;
  sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr);
  sqlite3_stmt* s = nullptr;
  sqlite3_prepare_v2(db, "SELECT rootpage FROM sqlite_master WHERE name = 'messages'", -1, &s, nullptr);
  const uint32_t root = sqlite3_step(s) == SQLITE_ROW ? static_cast<uint32_t>(sqlite3_column_int64(s, 0)) : 0;
  sqlite3_finalize(s);
  sqlite3_close(db);
  return root;
}

struct PageRead {
  std::vector<Row> rows;
  bool stopped = false;
  int64_t last_rowid = 0;
};

PageRead RowsByPages(const std::string& path, std::vector<int64_t> topics) {
  MappedFile file(path);
  std::optional<SqliteRowPages> pages = SqliteRowPages::Open(&file, RootPage(path), std::move(topics));
  EXPECT_TRUE(pages.has_value());
  PageRead out;
  if (!pages) return out;
  SqliteRowPages::Row r;
  while (pages->Next(&r))
    out.rows.emplace_back(r.rowid, r.topic_id, r.timestamp, std::vector<uint8_t>(r.data, r.data + r.size));
  out.stopped = pages->stopped();
  out.last_rowid = pages->last_rowid();
  return out;
}

std::string DatabasePath(const std::string& name) { return ::testing::TempDir() + "/" + name; }

TEST(SqliteRowPages, TheRowsSqliteReadsInItsOrder) {
  for (const Shape shape : {Shape{512, 0, 3000}, Shape{1024, 8, 2000}, Shape{4096, 0, 2000}, Shape{65536, 0, 3000}}) {
    SCOPED_TRACE(::testing::Message() << "page size " << shape.page_bytes << ", reserved " << shape.reserved_bytes);
    const std::string path = DatabasePath("pages.db3");
    sqlite3* db = WriteDatabase(path, shape);
    // Gaps in the rowids and free pages: a run of rows and every 7th row deleted.
    Exec(db, "DELETE FROM messages WHERE id BETWEEN 100 AND 300 OR id % 7 = 0");
    sqlite3_close(db);
    const std::vector<Row> expected = RowsBySqlite(path, "1,3");
    ASSERT_GT(expected.size(), 1000u);
    const PageRead read = RowsByPages(path, {1, 3});
    EXPECT_FALSE(read.stopped);
    EXPECT_TRUE(read.rows == expected) << read.rows.size() << " rows read, SQLite reads " << expected.size();
  }
}

// A file it does not read from a row on: it stops after the last row before, and the bag reader
// reads on through SQLite; what it delivers is what SQLite alone delivers.
class CollectingSink final : public MessageSink {
 public:
  int Wants(const BagConnection& c) override { return c.topic == "/a" || c.topic == "/c" ? (c.topic == "/a" ? 0 : 1) : -1; }
  void OnMessage(int slot, uint64_t time_ns, const uint8_t* data, size_t size) override {
    rows.emplace_back(0, slot == 0 ? 1 : 3, static_cast<int64_t>(time_ns), std::vector<uint8_t>(data, data + size));
  }
  std::vector<Row> rows;
};

std::vector<Row> WithoutRowids(std::vector<Row> rows) {
  for (Row& r : rows) std::get<0>(r) = 0;
  return rows;
}

std::vector<Row> ReadByTheBagReader(const std::string& path, std::vector<std::string>* notes) {
  Ros2SqliteFile file(path);
  CollectingSink sink;
  while (file.ReadBatch(&sink)) {
  }
  *notes = file.Notes();
  return sink.rows;
}

TEST(SqliteRowPages, StopsWhereItDoesNotReadAndSqliteReadsOn) {
  const std::string path = DatabasePath("text_row.db3");
  sqlite3* db = WriteDatabase(path, Shape{4096, 0, 20000});
  Exec(db, "UPDATE messages SET data = 'not a blob' WHERE id = 12000");  // a row of topic 1
  sqlite3_close(db);
  const PageRead read = RowsByPages(path, {1, 3});
  EXPECT_TRUE(read.stopped);
  EXPECT_EQ(read.last_rowid, 11999);
  std::vector<std::string> notes;
  const std::vector<Row> rows = ReadByTheBagReader(path, &notes);
  EXPECT_EQ(rows, WithoutRowids(RowsBySqlite(path, "1,3")));
  EXPECT_TRUE(notes.empty());
}

TEST(SqliteRowPages, AZeroedPageIsSqlitesToName) {
  const std::string path = DatabasePath("zeroed.db3");
  sqlite3_close(WriteDatabase(path, Shape{4096, 0, 30000}));
  const std::vector<Row> whole = RowsBySqlite(path, "1,3");
  {  // 40 pages zeroed at 60 % of the file, as tests/e2e/bags_damaged.sh does
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(0, std::ios::end);
    const std::streamoff pages = f.tellg() / 4096;
    f.seekp(pages * 6 / 10 * 4096);
    const std::vector<char> zeros(40 * 4096, 0);
    f.write(zeros.data(), static_cast<std::streamsize>(zeros.size()));
  }
  const PageRead read = RowsByPages(path, {1, 3});
  EXPECT_TRUE(read.stopped);
  std::vector<std::string> notes;
  const std::vector<Row> rows = ReadByTheBagReader(path, &notes);
  ASSERT_GE(rows.size(), read.rows.size());
  EXPECT_LT(rows.size(), whole.size());
  EXPECT_TRUE(std::equal(rows.begin(), rows.end(), WithoutRowids(whole).begin()));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("the database is damaged after its " + std::to_string(rows.size()) +
                          " readable messages (SQLite: "), std::string::npos) << notes[0];
}

TEST(SqliteRowPages, AWalDatabaseWhoseLogHoldsRowsIsReadBySqlite) {
  const std::string path = DatabasePath("wal.db3");
  sqlite3* writer = WriteDatabase(path, Shape{4096, 0, 5000, true});
  // The rows so far into the database file; then changes that stay in the log while the writer
  // is open: the file's own pages hold rows that are no longer the table's.
  Exec(writer, "PRAGMA wal_checkpoint(TRUNCATE)");
  Exec(writer, "UPDATE messages SET data = zeroblob(length(data)) WHERE id % 2 = 0");
  Exec(writer, "INSERT INTO messages(topic_id, timestamp, data) SELECT topic_id, timestamp + 1, data FROM messages");
  std::vector<std::string> notes;
  const std::vector<Row> rows = ReadByTheBagReader(path, &notes);
  const std::vector<Row> expected = WithoutRowids(RowsBySqlite(path, "1,3"));
  sqlite3_close(writer);
  ASSERT_GT(expected.size(), 3000u);
  EXPECT_EQ(rows, expected);
}

}  // namespace
}  // namespace sqlite_row_pages_test
}  // namespace accelcal::bags
