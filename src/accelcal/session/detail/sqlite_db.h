// Small RAII wrappers over the SQLite C API, used by the session store only.
//
// SqliteDb owns a connection, SqliteStatement a prepared statement (it borrows the connection,
// which must outlive it), SqliteTransaction a BEGIN IMMEDIATE ... COMMIT that rolls back when
// it is destroyed without Commit() (an exception on the way). Every failure throws
// accelcal::Error with SQLite's message and the database's path.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

struct sqlite3;
struct sqlite3_stmt;

namespace accelcal::detail {

class SqliteDb {
 public:
  // Opens `path`; `read_only` opens an existing file without writing, else it is created when
  // missing. Throws accelcal::Error when it cannot be opened.
  SqliteDb(const std::string& path, bool read_only);
  ~SqliteDb();
  SqliteDb(const SqliteDb&) = delete;
  SqliteDb& operator=(const SqliteDb&) = delete;

  // Runs one or more statements that return no rows (schema, PRAGMAs).
  void Exec(const std::string& sql);
  // The first column of the first row of `sql` as an integer (PRAGMA user_version, counts).
  std::int64_t QueryInt(const std::string& sql);

  sqlite3* handle() const { return db_; }
  const std::string& path() const { return path_; }
  // "session PATH: WHAT: SQLite's message" for the last error on this connection.
  std::string Describe(const std::string& what) const;

 private:
  sqlite3* db_ = nullptr;  // owned; closed in the destructor
  std::string path_;
};

class SqliteStatement {
 public:
  // Borrows `db`, which must outlive the statement.
  SqliteStatement(SqliteDb& db, const std::string& sql);
  ~SqliteStatement();
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;

  // Parameters are 1-based, as in SQLite. A NaN double is stored as NULL (SQLite does so anyway).
  SqliteStatement& Bind(int index, double value);
  SqliteStatement& Bind(int index, std::int64_t value);
  SqliteStatement& Bind(int index, int value) { return Bind(index, static_cast<std::int64_t>(value)); }
  SqliteStatement& Bind(int index, const std::string& value);
  SqliteStatement& BindBlob(int index, const std::vector<unsigned char>& bytes);
  SqliteStatement& BindNull(int index);

  // Steps once: true when a row is ready, false when done. Throws on an error (e.g. a UNIQUE
  // constraint).
  bool Step();
  // Runs a statement that returns no rows.
  void Run();

  // Columns are 0-based. NULL reads as NaN, 0, "" or an empty blob.
  double ColumnDouble(int index) const;
  std::int64_t ColumnInt(int index) const;
  std::string ColumnText(int index) const;
  std::vector<unsigned char> ColumnBlob(int index) const;
  bool ColumnIsNull(int index) const;
  // The stored type of a column in this row, and the bytes of a text or blob column (valid until
  // the next Step; empty for the others). For checksums over what SQLite gives back.
  enum class ColumnKind { kNull, kInteger, kReal, kText, kBlob };
  ColumnKind ColumnKindOf(int index) const;
  std::string_view ColumnBytes(int index) const;

 private:
  SqliteDb& db_;  // borrowed; outlives the statement
  sqlite3_stmt* stmt_ = nullptr;  // owned; finalized in the destructor
};

class SqliteTransaction {
 public:
  // BEGIN IMMEDIATE: takes the write lock now, so the transaction never fails half way for a
  // lock. Borrows `db`, which must outlive the transaction.
  explicit SqliteTransaction(SqliteDb& db);
  ~SqliteTransaction();  // rolls back unless committed
  SqliteTransaction(const SqliteTransaction&) = delete;
  SqliteTransaction& operator=(const SqliteTransaction&) = delete;

  // COMMIT: durable when it returns (with synchronous=FULL).
  void Commit();

 private:
  SqliteDb& db_;  // borrowed
  bool done_ = false;
};

}  // namespace accelcal::detail
