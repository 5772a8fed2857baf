// The store's schema (version kSessionSchemaVersion, kept in PRAGMA user_version; the file is
// marked as accelcal's by PRAGMA application_id):
//
//   session    one row: name, procedure, source, device, operator, created_utc, updated_utc,
//              state ('open' | 'done')
//   devices    serial (one row per device seen), first_seen_utc
//   captures   seq (recording order), step_id UNIQUE, capture_id, kind, label, radius_m, rpm,
//              up_axis, rejection_reason, n, mean_{x,y,z}_counts, cov_{xx,xy,xz,yy,yz,zz}_counts2,
//              t_first_s, t_last_s, mean_temp_c, samples (BLOB, see sample_blob.h), recorded_utc
//   inputs     (step_id, key) PRIMARY KEY, value, recorded_utc
//   steps_done step_id PRIMARY KEY, outcome, recorded_utc
//   results    seq, calibration_json (the calibration file's JSON text), recorded_utc
//
// NaN (no radius, no temperature) is stored as NULL. Times are UTC ISO 8601 text.
#pragma once

#include <string>

#include "accelcal/session/detail/sqlite_db.h"

namespace accelcal::detail {

inline constexpr int kSessionSchemaVersion = 1;
inline constexpr int kSessionApplicationId = 0x41434331;  // "ACC1"

// Creates the tables and the session row in a new, empty database (one transaction).
void CreateSessionSchema(SqliteDb& db, const std::string& name, const std::string& procedure,
                         const std::string& source);
// True when the database has no tables yet (a file just created).
bool IsEmptyDatabase(SqliteDb& db);
// Throws accelcal::Error when the file is not an accelcal session or has a schema version this
// build does not know ("written by a newer accelcal").
void CheckSessionSchema(SqliteDb& db);

}  // namespace accelcal::detail
