#include "accelcal/lab/detail/libpq_api.h"

#include <dlfcn.h>

#include <fmt/core.h>

#include "accelcal/lab/lab_error.h"

namespace accelcal::detail {
namespace {

constexpr const char* kLibPq = "libpq.so.5";

template <typename F>
void Load(void* library, const char* name, F* function) {
  void* symbol = dlsym(library, name);
  if (symbol == nullptr)
    throw LabError(fmt::format("{} has no {}: a libpq older than accelcal needs", kLibPq, name),
                   kSqlStateUnreachable);
  *function = reinterpret_cast<F>(symbol);
}

LibPq LoadLibPq() {
  // Never closed: the functions are used until the process ends.
  void* library = dlopen(kLibPq, RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr)
    throw LabError(fmt::format("the lab store needs PostgreSQL's client library {} (Debian package "
                               "libpq5): {}",
                               kLibPq, dlerror()),
                   kSqlStateUnreachable);
  LibPq pq{};
  Load(library, "PQconnectdbParams", &pq.connectdb_params);
  Load(library, "PQstatus", &pq.status);
  Load(library, "PQerrorMessage", &pq.error_message);
  Load(library, "PQfinish", &pq.finish);
  Load(library, "PQhost", &pq.host);
  Load(library, "PQport", &pq.port);
  Load(library, "PQdb", &pq.db);
  Load(library, "PQuser", &pq.user);
  Load(library, "PQexecParams", &pq.exec_params);
  Load(library, "PQexec", &pq.exec);
  Load(library, "PQresultStatus", &pq.result_status);
  Load(library, "PQresultErrorField", &pq.result_error_field);
  Load(library, "PQclear", &pq.clear);
  Load(library, "PQntuples", &pq.ntuples);
  Load(library, "PQgetvalue", &pq.getvalue);
  Load(library, "PQgetlength", &pq.getlength);
  Load(library, "PQgetisnull", &pq.getisnull);
  Load(library, "PQunescapeBytea", &pq.unescape_bytea);
  Load(library, "PQfreemem", &pq.freemem);
  Load(library, "PQcmdTuples", &pq.cmd_tuples);
  return pq;
}

}  // namespace

const LibPq& Pq() {
  static const LibPq pq = LoadLibPq();  // a throw leaves it unset: the next call tries again
  return pq;
}

}  // namespace accelcal::detail
