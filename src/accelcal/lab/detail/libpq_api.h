// libpq, PostgreSQL's C client, loaded when the lab's store is first used (dlopen), not linked:
// linked, its 21 shared libraries (OpenSSL, Kerberos, LDAP, GnuTLS, ...) would load at every
// start of accelcal, about 5 ms of CPU each time (measured: a program linked with -lpq against
// one without, 300 runs), for the many commands that never reach a lab. The declarations are
// libpq-fe.h's (Debian's libpq-dev); the library is libpq.so.5 (Debian's libpq5; its soname
// has been 5 since PostgreSQL 8.0).
#pragma once

#include <libpq-fe.h>

namespace accelcal::detail {

struct LibPq {
  decltype(&::PQconnectdbParams) connectdb_params;
  decltype(&::PQstatus) status;
  decltype(&::PQerrorMessage) error_message;
  decltype(&::PQfinish) finish;
  decltype(&::PQhost) host;
  decltype(&::PQport) port;
  decltype(&::PQdb) db;
  decltype(&::PQuser) user;
  decltype(&::PQexecParams) exec_params;
  decltype(&::PQexec) exec;
  decltype(&::PQresultStatus) result_status;
  decltype(&::PQresultErrorField) result_error_field;
  decltype(&::PQclear) clear;
  decltype(&::PQntuples) ntuples;
  decltype(&::PQgetvalue) getvalue;
  decltype(&::PQgetlength) getlength;
  decltype(&::PQgetisnull) getisnull;
  decltype(&::PQunescapeBytea) unescape_bytea;
  decltype(&::PQfreemem) freemem;
  decltype(&::PQcmdTuples) cmd_tuples;
};

// libpq's functions, loaded on the first call (thread-safe). Throws LabError (SQLSTATE 08001)
// naming the library and the package when it cannot be loaded.
const LibPq& Pq();

}  // namespace accelcal::detail
