#include "accelcal/session/detail/sqlite_db.h"

#include <cmath>

#include <fmt/core.h>
#include <sqlite3.h>

#include "accelcal/base/error.h"

namespace accelcal::detail {

namespace {

// Opens `path` with `flags`; throws accelcal::Error "session PATH: cannot open: ...".
sqlite3* OpenConnection(const std::string& path, int flags) {
  sqlite3* db = nullptr;
  const int rc = sqlite3_open_v2(path.c_str(), &db, flags | SQLITE_OPEN_NOMUTEX, nullptr);
  if (rc != SQLITE_OK) {
    const std::string message = db ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
    sqlite3_close(db);
    throw Error(fmt::format("session {}: cannot open: {}", path, message));
  }
  sqlite3_extended_result_codes(db, 1);
  // A reader may meet a writer's checkpoint; wait for it rather than fail at once.
  sqlite3_busy_timeout(db, 5000);
  return db;
}

// The result code of a first read of the schema on `db`.
int FirstRead(sqlite3* db) {
  return sqlite3_exec(db, "SELECT count(*) FROM sqlite_master", nullptr, nullptr, nullptr);
}

}  // namespace

SqliteDb::SqliteDb(const std::string& path, bool read_only) : path_(path) {
  if (!read_only) {
    db_ = OpenConnection(path, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
    return;
  }
  db_ = OpenConnection(path, SQLITE_OPEN_READONLY);
  // A writer killed in the middle of a transaction in rollback-journal mode (the wizard's clean
  // close switches the file back to one) leaves a hot journal: the committed state is in the
  // journal, and only a connection that may write can put it back. A read-only connection
  // cannot read the file until then ("attempt to write a readonly database"); the same for a WAL
  // index left to rebuild. Such a file is recovered once by a connection that may write (SQLite
  // rolls back only a journal no live writer holds), then read as asked.
  const int rc = FirstRead(db_);
  if ((rc & 0xff) != SQLITE_READONLY) return;  // _ROLLBACK, _RECOVERY: a read that must write
  sqlite3_close(db_);
  db_ = nullptr;
  sqlite3* writer = nullptr;
  try {
    writer = OpenConnection(path, SQLITE_OPEN_READWRITE);
  } catch (const Error& e) {
    throw Error(fmt::format(
        "session {}: a write was interrupted (the program stopped mid-write) and the file must "
        "be put back to its last committed state, which needs write access to it and its "
        "folder: {}; run the wizard on it once, or copy the folder where it can be written",
        path, e.what()));
  }
  const int recovered = FirstRead(writer);
  const std::string message = sqlite3_errmsg(writer);
  sqlite3_close(writer);
  if (recovered != SQLITE_OK)
    throw Error(fmt::format("session {}: cannot recover from an interrupted write: {}", path,
                            message));
  db_ = OpenConnection(path, SQLITE_OPEN_READONLY);
}

SqliteDb::~SqliteDb() { sqlite3_close(db_); }

std::string SqliteDb::Describe(const std::string& what) const {
  return fmt::format("session {}: {}: {}", path_, what, sqlite3_errmsg(db_));
}

void SqliteDb::Exec(const std::string& sql) {
  char* message = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &message) != SQLITE_OK) {
    const std::string text = message ? message : "unknown error";
    sqlite3_free(message);
    throw Error(fmt::format("session {}: {}", path_, text));
  }
}

std::int64_t SqliteDb::QueryInt(const std::string& sql) {
  SqliteStatement statement(*this, sql);
  return statement.Step() ? statement.ColumnInt(0) : 0;
}

SqliteStatement::SqliteStatement(SqliteDb& db, const std::string& sql) : db_(db) {
  if (sqlite3_prepare_v2(db.handle(), sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK)
    throw Error(db_.Describe("cannot prepare a query"));
}

SqliteStatement::~SqliteStatement() { sqlite3_finalize(stmt_); }

namespace {
void Check(int rc, const SqliteDb& db) {
  if (rc != SQLITE_OK) throw Error(db.Describe("cannot bind a value"));
}
}  // namespace

SqliteStatement& SqliteStatement::Bind(int index, double value) {
  if (std::isnan(value)) return BindNull(index);
  Check(sqlite3_bind_double(stmt_, index, value), db_);
  return *this;
}

SqliteStatement& SqliteStatement::Bind(int index, std::int64_t value) {
  Check(sqlite3_bind_int64(stmt_, index, value), db_);
  return *this;
}

SqliteStatement& SqliteStatement::Bind(int index, const std::string& value) {
  Check(sqlite3_bind_text(stmt_, index, value.data(), static_cast<int>(value.size()),
                          SQLITE_TRANSIENT), db_);
  return *this;
}

SqliteStatement& SqliteStatement::BindBlob(int index, const std::vector<unsigned char>& bytes) {
  // A zero-length blob, not NULL, for an empty vector.
  Check(sqlite3_bind_blob64(stmt_, index, bytes.empty() ? "" : static_cast<const void*>(bytes.data()),
                            bytes.size(), SQLITE_TRANSIENT), db_);
  return *this;
}

SqliteStatement& SqliteStatement::BindNull(int index) {
  Check(sqlite3_bind_null(stmt_, index), db_);
  return *this;
}

bool SqliteStatement::Step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  throw Error(db_.Describe("query failed"));
}

void SqliteStatement::Run() {
  while (Step()) {
  }
}

double SqliteStatement::ColumnDouble(int index) const {
  return ColumnIsNull(index) ? std::nan("") : sqlite3_column_double(stmt_, index);
}

std::int64_t SqliteStatement::ColumnInt(int index) const { return sqlite3_column_int64(stmt_, index); }

std::string SqliteStatement::ColumnText(int index) const {
  const unsigned char* text = sqlite3_column_text(stmt_, index);
  if (!text) return {};
  return std::string(reinterpret_cast<const char*>(text),
                     static_cast<size_t>(sqlite3_column_bytes(stmt_, index)));
}

std::vector<unsigned char> SqliteStatement::ColumnBlob(int index) const {
  const auto* data = static_cast<const unsigned char*>(sqlite3_column_blob(stmt_, index));
  const int size = sqlite3_column_bytes(stmt_, index);
  if (!data || size <= 0) return {};
  return std::vector<unsigned char>(data, data + size);
}

bool SqliteStatement::ColumnIsNull(int index) const {
  return sqlite3_column_type(stmt_, index) == SQLITE_NULL;
}

SqliteStatement::ColumnKind SqliteStatement::ColumnKindOf(int index) const {
  switch (sqlite3_column_type(stmt_, index)) {
    case SQLITE_INTEGER: return ColumnKind::kInteger;
    case SQLITE_FLOAT: return ColumnKind::kReal;
    case SQLITE_TEXT: return ColumnKind::kText;
    case SQLITE_BLOB: return ColumnKind::kBlob;
    default: return ColumnKind::kNull;
  }
}

std::string_view SqliteStatement::ColumnBytes(int index) const {
  const ColumnKind kind = ColumnKindOf(index);
  if (kind != ColumnKind::kText && kind != ColumnKind::kBlob) return {};
  // The pointer first, then the size (sqlite.org/c3ref/column_blob.html, "safest policy").
  const void* data = kind == ColumnKind::kText ? static_cast<const void*>(sqlite3_column_text(stmt_, index))
                                               : sqlite3_column_blob(stmt_, index);
  const int size = sqlite3_column_bytes(stmt_, index);
  if (!data || size <= 0) return {};
  return std::string_view(static_cast<const char*>(data), static_cast<size_t>(size));
}

SqliteTransaction::SqliteTransaction(SqliteDb& db) : db_(db) { db_.Exec("BEGIN IMMEDIATE"); }

SqliteTransaction::~SqliteTransaction() {
  if (!done_) sqlite3_exec(db_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
}

void SqliteTransaction::Commit() {
  db_.Exec("COMMIT");
  done_ = true;
}

}  // namespace accelcal::detail
