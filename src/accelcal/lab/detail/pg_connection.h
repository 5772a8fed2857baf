// Small RAII wrappers over libpq (PostgreSQL's C client), used by the lab store only: the one
// place in accelcal that links libpq (scripts/check_layers.sh).
//
// PgConnection connects with libpq's own settings and nothing of ours: the PG* environment
// variables (PGHOST, PGPORT, PGDATABASE, PGUSER, PGSERVICE, PGPASSFILE, PGSSLMODE, ...), the
// connection service file (PGSERVICEFILE, ~/.pg_service.conf) and the password file
// (~/.pgpass); accelcal never takes a password. Every statement runs with its parameters sent
// apart from its text (PQexecParams): nothing typed at a bench is ever spliced into SQL.
// Failures throw LabError with the server's SQLSTATE.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

struct pg_conn;
struct pg_result;

namespace accelcal::detail {

// One parameter of a statement: text, NULL, or bytes sent as binary (a bytea).
struct PgParam {
  std::optional<std::string> value;  // nullopt: NULL
  bool binary = false;
};
PgParam PgText(std::string text);
PgParam PgNull();
PgParam PgBytes(std::string bytes);
PgParam PgInt(long long value);

class PgResult {
 public:
  explicit PgResult(pg_result* result);  // owned
  ~PgResult();
  PgResult(PgResult&& other) noexcept;
  PgResult(const PgResult&) = delete;
  PgResult& operator=(const PgResult&) = delete;

  int rows() const;
  // Columns are 0-based. NULL reads as "" (IsNull tells).
  std::string Text(int row, int column) const;
  bool IsNull(int row, int column) const;
  long long Int(int row, int column) const;
  // A bytea column of a text-format result, decoded to its bytes.
  std::string Bytes(int row, int column) const;
  // Rows affected by an INSERT/UPDATE/DELETE.
  long long Affected() const;

 private:
  pg_result* result_ = nullptr;
};

class PgConnection {
 public:
  // Connects with libpq's settings (see above), application name "accelcal", the session's time
  // zone UTC. The wait for the server (libpq's connect_timeout, for each address of the host):
  // `connect_timeout_s` > 0 caps it whatever the settings say (PGCONNECT_TIMEOUT wins only when
  // shorter); 0 takes the settings', else kDefaultConnectTimeoutS. Throws LabError (SQLSTATE
  // 08001) with libpq's reason and where it tried.
  static constexpr int kDefaultConnectTimeoutS = 10;
  explicit PgConnection(int connect_timeout_s = 0);
  ~PgConnection();
  PgConnection(const PgConnection&) = delete;
  PgConnection& operator=(const PgConnection&) = delete;

  // One statement, its parameters $1, $2, ... sent apart. Throws LabError.
  PgResult Exec(const std::string& sql, const std::vector<PgParam>& params = {});
  // Several statements without parameters (a migration's script). Throws LabError.
  void ExecScript(const std::string& sql);
  // "database lab on /tmp/pg:5433 as bench_a"
  const std::string& Where() const { return where_; }

 private:
  [[noreturn]] void Fail(pg_result* result, const std::string& what);
  pg_conn* conn_ = nullptr;  // owned
  std::string where_;
};

// BEGIN ... COMMIT; rolls back when destroyed without Commit() (an exception on the way). A
// connection lost before COMMIT's answer leaves the outcome to the server: the publisher's
// natural key makes the retry find what committed (lab_store.h).
class PgTransaction {
 public:
  explicit PgTransaction(PgConnection& db);
  ~PgTransaction();
  PgTransaction(const PgTransaction&) = delete;
  PgTransaction& operator=(const PgTransaction&) = delete;
  void Commit();

 private:
  PgConnection& db_;  // borrowed
  bool done_ = false;
};

}  // namespace accelcal::detail
