#include "accelcal/lab/detail/pg_connection.h"

#include <cstdlib>
#include <utility>

#include <fmt/core.h>
#include "accelcal/lab/detail/libpq_api.h"
#include "accelcal/lab/lab_error.h"

namespace accelcal::detail {

PgParam PgText(std::string text) { return {std::move(text), false}; }
PgParam PgNull() { return {std::nullopt, false}; }
PgParam PgBytes(std::string bytes) { return {std::move(bytes), true}; }
PgParam PgInt(long long value) { return {std::to_string(value), false}; }

PgResult::PgResult(pg_result* result) : result_(result) {}
PgResult::~PgResult() { Pq().clear(result_); }
PgResult::PgResult(PgResult&& other) noexcept : result_(std::exchange(other.result_, nullptr)) {}

int PgResult::rows() const { return Pq().ntuples(result_); }

std::string PgResult::Text(int row, int column) const {
  return std::string(Pq().getvalue(result_, row, column),
                     static_cast<size_t>(Pq().getlength(result_, row, column)));
}

bool PgResult::IsNull(int row, int column) const { return Pq().getisnull(result_, row, column) == 1; }

long long PgResult::Int(int row, int column) const {
  const std::string text = Text(row, column);
  char* end = nullptr;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0')
    throw LabError(fmt::format("the lab store answered '{}' where a number was expected", text), "");
  return value;
}

std::string PgResult::Bytes(int row, int column) const {
  size_t length = 0;
  unsigned char* bytes = Pq().unescape_bytea(
      reinterpret_cast<const unsigned char*>(Pq().getvalue(result_, row, column)), &length);
  if (bytes == nullptr) throw LabError("the lab store's bytes could not be decoded (out of memory)", "");
  std::string out(reinterpret_cast<const char*>(bytes), length);
  Pq().freemem(bytes);
  return out;
}

long long PgResult::Affected() const {
  const char* n = Pq().cmd_tuples(result_);
  return n[0] == '\0' ? 0 : std::atoll(n);
}

namespace {

// "database lab on /tmp/pg:5433 as bench_a": where a connection went (or tried to), from libpq's
// resolved settings (never the password).
std::string WhereOf(pg_conn* conn) {
  const char* host = Pq().host(conn);
  const char* port = Pq().port(conn);
  const char* db = Pq().db(conn);
  const char* user = Pq().user(conn);
  return fmt::format("database {} on {}:{} as {}", db ? db : "?", host && *host ? host : "?",
                     port && *port ? port : "?", user ? user : "?");
}

// libpq's messages end with a newline and may span lines; ours are one line.
std::string OneLine(const std::string& text) {
  std::string line;
  for (char c : text) {
    const bool blank = c == '\n' || c == '\t' || c == '\r' || c == ' ';
    if (blank && (line.empty() || line.back() == ' ')) continue;
    line += blank ? ' ' : c;
  }
  while (!line.empty() && line.back() == ' ') line.pop_back();
  return line;
}

// "an insert", "an update", ...: what a statement was, for its error message.
std::string StatementKind(const std::string& sql) {
  const std::string verb = sql.substr(0, sql.find_first_of(" \n"));
  if (verb == "INSERT") return "an insert";
  if (verb == "UPDATE") return "an update";
  if (verb == "DELETE") return "a delete";
  if (verb == "SELECT" || verb == "WITH") return "a query";
  return "a statement";
}

// The connect_timeout to pass libpq (empty: none, libpq reads the settings'). Without a cap, a
// bounded wait when no timeout is set anywhere we can see; with one, the cap, or the user's
// PGCONNECT_TIMEOUT when it is shorter (a service file's is not visible here: the cap wins).
std::string ConnectTimeoutValue(int cap_s) {
  const char* env = std::getenv("PGCONNECT_TIMEOUT");
  if (cap_s <= 0) {
    if (env != nullptr || std::getenv("PGSERVICE") != nullptr) return "";
    return std::to_string(PgConnection::kDefaultConnectTimeoutS);
  }
  if (env != nullptr) {
    char* end = nullptr;
    const long user_s = std::strtol(env, &end, 10);
    if (end != env && *end == '\0' && user_s > 0 && user_s < cap_s) return std::to_string(user_s);
  }
  return std::to_string(cap_s);
}

}  // namespace

PgConnection::PgConnection(int connect_timeout_s) {
  // Only what libpq reads itself, plus defaults that never override the user's: the application
  // name (fallback_), and a bounded connect (ConnectTimeoutValue).
  std::vector<const char*> keys = {"fallback_application_name"};
  std::vector<const char*> values = {"accelcal"};
  const std::string timeout = ConnectTimeoutValue(connect_timeout_s);
  if (!timeout.empty()) {
    keys.push_back("connect_timeout");
    values.push_back(timeout.c_str());
  }
  keys.push_back(nullptr);
  values.push_back(nullptr);
  conn_ = Pq().connectdb_params(keys.data(), values.data(), 0);
  if (conn_ == nullptr) throw LabError("cannot reach the lab store: out of memory", kSqlStateUnreachable);
  where_ = WhereOf(conn_);
  if (Pq().status(conn_) != CONNECTION_OK) {
    const std::string reason = OneLine(Pq().error_message(conn_));
    Pq().finish(conn_);
    conn_ = nullptr;
    throw LabError(fmt::format("cannot reach the lab store ({}): {}", where_, reason), kSqlStateUnreachable);
  }
  // Times are exchanged as UTC text (the store keeps timestamptz); the server's notices ("role
  // is already a member") are not the technician's business, its warnings and errors are.
  ExecScript("SET TimeZone = 'UTC'; SET DateStyle = 'ISO'; SET client_min_messages = warning");
}

PgConnection::~PgConnection() { Pq().finish(conn_); }

void PgConnection::Fail(pg_result* result, const std::string& what) {
  std::string sqlstate;
  std::string message;
  if (result != nullptr) {
    if (const char* state = Pq().result_error_field(result, PG_DIAG_SQLSTATE)) sqlstate = state;
    if (const char* primary = Pq().result_error_field(result, PG_DIAG_MESSAGE_PRIMARY)) message = primary;
    if (const char* detail = Pq().result_error_field(result, PG_DIAG_MESSAGE_DETAIL))
      message += std::string(" (") + detail + ")";
    Pq().clear(result);
  }
  if (Pq().status(conn_) != CONNECTION_OK) {
    if (sqlstate.empty() || sqlstate.rfind("08", 0) != 0) sqlstate = kSqlStateConnectionLost;
    if (message.empty()) message = OneLine(Pq().error_message(conn_));
    throw LabError(fmt::format("lost the connection to the lab store ({}) {}: {}", where_, what, message),
                   sqlstate);
  }
  if (message.empty()) message = OneLine(Pq().error_message(conn_));
  if (sqlstate == kSqlStateRefused)
    throw LabError(fmt::format("the lab store refused {} ({}): {}", what, where_, message), sqlstate);
  throw LabError(fmt::format("the lab store failed {} ({}): {}", what, where_, message), sqlstate);
}

PgResult PgConnection::Exec(const std::string& sql, const std::vector<PgParam>& params) {
  std::vector<const char*> values;
  std::vector<int> lengths, formats;
  for (const PgParam& p : params) {
    values.push_back(p.value ? p.value->data() : nullptr);
    lengths.push_back(p.value ? static_cast<int>(p.value->size()) : 0);
    formats.push_back(p.binary ? 1 : 0);
  }
  pg_result* result = Pq().exec_params(conn_, sql.c_str(), static_cast<int>(params.size()), nullptr,
                                       values.data(), lengths.data(), formats.data(), 0);
  const ExecStatusType status = result ? Pq().result_status(result) : PGRES_FATAL_ERROR;
  if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) {
    Fail(result, StatementKind(sql));
  }
  return PgResult(result);
}

void PgConnection::ExecScript(const std::string& sql) {
  pg_result* result = Pq().exec(conn_, sql.c_str());
  const ExecStatusType status = result ? Pq().result_status(result) : PGRES_FATAL_ERROR;
  if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) Fail(result, "a script");
  Pq().clear(result);
}

PgTransaction::PgTransaction(PgConnection& db) : db_(db) { db_.ExecScript("BEGIN"); }

PgTransaction::~PgTransaction() {
  if (done_) return;
  try {
    db_.ExecScript("ROLLBACK");
  } catch (const LabError&) {
    // The connection is gone: the server rolls the transaction back itself.
  }
}

void PgTransaction::Commit() {
  db_.ExecScript("COMMIT");
  done_ = true;
}

}  // namespace accelcal::detail
