#include "accelcal/bags/ros2_sqlite_file.h"

#include <sqlite3.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <map>

#include <fmt/format.h>

#include "accelcal/base/error.h"

namespace accelcal::bags {
namespace {

// Rows handed over per batch.
constexpr int kRowsPerBatch = 8192;

std::string ColumnText(sqlite3_stmt* s, int column) {
  const unsigned char* text = sqlite3_column_text(s, column);
  return text == nullptr ? std::string() : std::string(reinterpret_cast<const char*>(text));
}

// An owned prepared statement.
class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &s_, nullptr) != SQLITE_OK) s_ = nullptr;
  }
  ~Statement() { sqlite3_finalize(s_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  sqlite3_stmt* get() const { return s_; }

 private:
  sqlite3_stmt* s_ = nullptr;
};

// The names of the database's tables; false with *error when SQLite cannot list them (a file
// that is not a database, or is damaged where its schema lies).
bool TableNames(sqlite3* db, std::vector<std::string>* names, std::string* error) {
  Statement s(db, "SELECT name FROM sqlite_master WHERE type = 'table'");
  if (s.get() == nullptr) {
    *error = sqlite3_errmsg(db);
    return false;
  }
  int rc;
  while ((rc = sqlite3_step(s.get())) == SQLITE_ROW) names->push_back(ColumnText(s.get(), 0));
  if (rc != SQLITE_DONE) *error = sqlite3_errmsg(db);
  return rc == SQLITE_DONE;
}

bool Holds(const std::vector<std::string>& names, const char* name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

sqlite3* OpenReadOnly(const std::string& path, std::string* error) {
  sqlite3* db = nullptr;
  const int rc = sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY | SQLITE_OPEN_NOMUTEX,
                                 nullptr);
  if (rc != SQLITE_OK) {
    *error = db != nullptr ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
    sqlite3_close(db);
    return nullptr;
  }
  return db;
}

bool SameWord(const std::string& a, const char* b) {
  return std::equal(a.begin(), a.end(), b, b + std::strlen(b),
                    [](char x, char y) { return std::tolower(static_cast<unsigned char>(x)) == y; });
}

// True when the messages table is (id INTEGER PRIMARY KEY, topic_id, timestamp, data) in this
// order, as rosbag2 creates it (its values' types are checked row by row).
bool RosbagMessagesColumns(sqlite3* db) {
  Statement s(db, "PRAGMA table_info(messages)");
  const char* const names[] = {"id", "topic_id", "timestamp", "data"};
  size_t n = 0;
  while (s.get() != nullptr && sqlite3_step(s.get()) == SQLITE_ROW) {
    if (n >= 4 || ColumnText(s.get(), 1) != names[n]) return false;
    if (n == 0 && (!SameWord(ColumnText(s.get(), 2), "integer") || sqlite3_column_int(s.get(), 5) != 1))
      return false;
    ++n;
  }
  return n == 4;
}

}  // namespace

bool Ros2SqliteFile::HoldsRosbag2Tables(const std::string& path) {
  std::string error;
  sqlite3* db = OpenReadOnly(path, &error);
  if (db == nullptr) return false;
  std::vector<std::string> names;
  const bool holds = TableNames(db, &names, &error) && Holds(names, "topics") && Holds(names, "messages");
  sqlite3_close(db);
  return holds;
}

Ros2SqliteFile::Ros2SqliteFile(const std::string& path) : path_(path) {
  std::string error;
  db_ = OpenReadOnly(path, &error);
  if (db_ == nullptr) throw Error(fmt::format("cannot open '{}': {}", path, error));
  std::vector<std::string> names;
  if (!TableNames(db_, &names, &error)) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw Error(fmt::format("{}: its SQLite database cannot be read (SQLite: {}): damaged, or cut "
                            "short where its tables are described", path, error));
  }
  if (!Holds(names, "topics") || !Holds(names, "messages")) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw Error(fmt::format("{}: not a ROS 2 bag (an SQLite file without rosbag2's topics and "
                            "messages tables)", path));
  }
  has_definitions_ = Holds(names, "message_definitions");
  ReadTopics();
}

Ros2SqliteFile::~Ros2SqliteFile() {
  sqlite3_finalize(rows_);
  sqlite3_close(db_);
}

void Ros2SqliteFile::ReadTopics() {
  // Jazzy's bags hold the definitions of their types (rosbag2 schema 4); older ones do not.
  std::map<std::string, std::pair<std::string, std::string>> definitions;
  if (has_definitions_) {
    Statement s(db_, "SELECT topic_type, encoding, encoded_message_definition FROM message_definitions");
    while (s.get() != nullptr && sqlite3_step(s.get()) == SQLITE_ROW)
      definitions[ColumnText(s.get(), 0)] = {ColumnText(s.get(), 1), ColumnText(s.get(), 2)};
  }
  Statement s(db_, "SELECT id, name, type, serialization_format FROM topics ORDER BY id");
  if (s.get() == nullptr) Fail(std::string("its topics table: ") + sqlite3_errmsg(db_));
  int rc;
  while ((rc = sqlite3_step(s.get())) == SQLITE_ROW) {
    Topic t;
    t.id = sqlite3_column_int64(s.get(), 0);
    t.connection.topic = ColumnText(s.get(), 1);
    t.connection.type = ColumnText(s.get(), 2);
    t.connection.encoding = ColumnText(s.get(), 3);
    const auto def = definitions.find(t.connection.type);
    if (def != definitions.end() && !def->second.second.empty()) {
      t.connection.schema_encoding = def->second.first;
      t.connection.schema = def->second.second;
    }
    topics_.push_back(std::move(t));
  }
  if (rc != SQLITE_DONE) Fail(std::string("its topics table: ") + sqlite3_errmsg(db_));
}

std::optional<std::vector<TopicSummary>> Ros2SqliteFile::IndexedTopics(bool with_counts) {
  std::vector<TopicSummary> out;
  std::map<int64_t, size_t> by_id;
  for (const Topic& t : topics_) {
    auto it = std::find_if(out.begin(), out.end(),
                           [&](const TopicSummary& s) { return s.name == t.connection.topic; });
    if (it == out.end()) {
      out.push_back({t.connection.topic, t.connection.type, with_counts ? 0 : -1, 0, 0});
      it = out.end() - 1;
    }
    by_id[t.id] = static_cast<size_t>(it - out.begin());
  }
  if (!with_counts) return out;
  Statement s(db_, "SELECT topic_id, COUNT(*), MIN(timestamp), MAX(timestamp) FROM messages "
                   "GROUP BY topic_id");
  if (s.get() == nullptr) Fail(std::string("its messages table: ") + sqlite3_errmsg(db_));
  int rc;
  while ((rc = sqlite3_step(s.get())) == SQLITE_ROW) {
    const auto id = by_id.find(sqlite3_column_int64(s.get(), 0));
    if (id == by_id.end()) continue;  // rows of a topic the topics table lacks
    TopicSummary& t = out[id->second];
    t.messages += sqlite3_column_int64(s.get(), 1);
    const auto first = static_cast<uint64_t>(sqlite3_column_int64(s.get(), 2));
    const auto last = static_cast<uint64_t>(sqlite3_column_int64(s.get(), 3));
    if (t.first_ns == 0 || first < t.first_ns) t.first_ns = first;
    t.last_ns = std::max(t.last_ns, last);
  }
  if (rc != SQLITE_DONE) {
    notes_.push_back(fmt::format("its messages could not all be counted (SQLite: {})",
                                 sqlite3_errmsg(db_)));
    for (TopicSummary& t : out) t.messages = -1;
  }
  return out;
}

// The wanted topics' rows, in the order they were written: from the pages when it can.
void Ros2SqliteFile::StartReading(MessageSink* sink) {
  started_ = true;
  for (Topic& t : topics_) {
    t.slot = sink->Wants(t.connection);
    if (t.slot >= 0) wanted_ids_.push_back(t.id);
  }
  if (wanted_ids_.empty()) {
    done_ = true;
    return;
  }
  if (!StartReadingPages()) PrepareRows(std::nullopt);
}

// The rows read from the file's pages (sqlite_row_pages.h), inside a read transaction held to
// the end so that no writer changes them meanwhile; false when the file is not one it reads (a
// WAL database whose log holds pages, a table of another shape).
bool Ros2SqliteFile::StartReadingPages() {
  if (sqlite3_exec(db_, "BEGIN", nullptr, nullptr, nullptr) != SQLITE_OK) return false;
  int64_t root = 0;
  {
    Statement s(db_, "SELECT rootpage FROM sqlite_master WHERE type = 'table' AND name = 'messages'");
    if (s.get() == nullptr || sqlite3_step(s.get()) != SQLITE_ROW) return false;
    root = sqlite3_column_int64(s.get(), 0);
  }
  if (root < 2 || root > UINT32_MAX || !RosbagMessagesColumns(db_)) return false;
  try {
    mapped_ = std::make_unique<MappedFile>(path_);
  } catch (const Error&) {
    return false;
  }
  pages_ = SqliteRowPages::Open(mapped_.get(), static_cast<uint32_t>(root), wanted_ids_);
  struct stat wal {};
  if (pages_ && pages_->read_version() == 2 && ::stat((path_ + "-wal").c_str(), &wal) == 0 && wal.st_size > 0)
    pages_.reset();  // WAL: the newest pages may be in the log
  if (!pages_) mapped_.reset();
  return pages_.has_value();
}

void Ros2SqliteFile::PrepareRows(std::optional<int64_t> after_rowid) {
  std::string ids;
  for (const int64_t id : wanted_ids_) ids += (ids.empty() ? "" : ",") + std::to_string(id);
  const std::string sql = fmt::format("SELECT topic_id, timestamp, data FROM messages WHERE topic_id IN ({}){} "
                                      "ORDER BY id", ids, after_rowid ? " AND id > ?1" : "");
  if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &rows_, nullptr) != SQLITE_OK)
    Fail(std::string("its messages table: ") + sqlite3_errmsg(db_));
  if (after_rowid) sqlite3_bind_int64(rows_, 1, *after_rowid);
}

// The topics' slots by id: a handful of topics, looked up by a short scan.
int Ros2SqliteFile::SlotOf(int64_t topic_id) const {
  int slot = -1;
  for (const Topic& t : topics_)
    if (t.id == topic_id) slot = t.slot;
  return slot;
}

bool Ros2SqliteFile::ReadBatch(MessageSink* sink) {
  if (!started_) StartReading(sink);
  if (done_) return false;
  int n = 0;
  if (pages_) {
    SqliteRowPages::Row row;
    for (; n < kRowsPerBatch; ++n) {
      if (!pages_->Next(&row)) break;
      ++rows_read_;
      const int slot = SlotOf(row.topic_id);
      if (slot >= 0) sink->OnMessage(slot, static_cast<uint64_t>(row.timestamp), row.data, row.size);
    }
    if (n == kRowsPerBatch) return true;
    if (!pages_->stopped()) {
      done_ = true;
      return true;
    }
    // Something the page reader does not read: SQLite goes on from the last row it read.
    PrepareRows(pages_->read_any() ? std::optional<int64_t>(pages_->last_rowid()) : std::nullopt);
    pages_.reset();
    mapped_.reset();
  }
  for (; n < kRowsPerBatch; ++n) {
    const int rc = sqlite3_step(rows_);
    if (rc == SQLITE_DONE) {
      done_ = true;
      return true;
    }
    if (rc != SQLITE_ROW) {
      notes_.push_back(fmt::format("the database is damaged after its {} readable messages "
                                   "(SQLite: {}): read up to there", rows_read_,
                                   sqlite3_errmsg(db_)));
      done_ = true;
      return true;
    }
    ++rows_read_;
    const int slot = SlotOf(sqlite3_column_int64(rows_, 0));
    if (slot < 0) continue;
    const auto time_ns = static_cast<uint64_t>(sqlite3_column_int64(rows_, 1));
    const auto* data = static_cast<const uint8_t*>(sqlite3_column_blob(rows_, 2));
    const int size = sqlite3_column_bytes(rows_, 2);
    sink->OnMessage(slot, time_ns, data, static_cast<size_t>(size));
  }
  return true;
}

void Ros2SqliteFile::Fail(const std::string& what) const {
  throw Error(fmt::format("{}: {}", path_, what));
}

}  // namespace accelcal::bags
