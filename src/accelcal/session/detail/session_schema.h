// The store's schema (version kSessionSchemaVersion, kept in PRAGMA user_version; the file is
// marked as accelcal's by PRAGMA application_id):
//
//   session    one row: name, procedure, source, device, operator, created_utc, updated_utc,
//              state ('open' | 'done'), uuid (version 6: the session's identity wherever it is
//              copied or published, base/uuid.h; given to older files when they are migrated)
//   devices    serial (one row per device seen), first_seen_utc
//   captures   seq (recording order), step_id UNIQUE, capture_id, kind, label, radius_m, rpm,
//              up_axis, rejection_reason, n, mean_{x,y,z}_counts,
//              comoment_{xx,xy,xz,yy,yz,zz}_counts2 (sum of (x - mean)(y - mean), version 3),
//              t_first_s, t_last_s, mean_temp_c, samples (BLOB, see sample_blob.h), recorded_utc,
//              checksum (of every other column but superseded_by, row_checksum.h; version 4),
//              superseded_by (version 5: the step id of the capture that replaced this one when
//              it was taken again; NULL: current. A mark set after the row was written, so it
//              is outside the checksum)
//              sensor (version 7: which of the session's sensors, 0 the first; UNIQUE
//              (step_id, sensor) replaces step_id UNIQUE; covered by the checksum)
//   sensors    (version 7) sensor PRIMARY KEY, serial UNIQUE, sensor_to_plate (9 numbers, row
//              by row), offset_m (3 numbers), source, fixture_name, recorded_utc: the session's
//              sensors (issue 31); no row: one sensor, the session's device
//   inputs     (step_id, key) PRIMARY KEY, value, recorded_utc
//   steps_done step_id PRIMARY KEY, outcome, recorded_utc
//   results    seq, calibration_json (the calibration file's JSON text), recorded_utc, sensor
//              (version 7: whose calibration; 0 the first)
//   record_chunks  (step_id, chunk_index) PRIMARY KEY, n, t_first_s, t_last_s, wall_end_s,
//              samples (BLOB, see sample_blob.h), recorded_utc, checksum (version 4): a record
//              step's samples, one row per chunk (version 2)
//   record_gaps    (step_id, before_chunk) PRIMARY KEY, t_start_s, t_end_s, reason,
//              recorded_utc: the hole just before chunk `before_chunk` (version 2)
//   lab_certificates  sensor_index PRIMARY KEY, certificate_number, lab, published_utc: the
//              number a lab's store assigned to the calibration of each sensor when the session
//              was published there (version 6; accelcal lab publish, docs/lab.md)
//
// An older version is migrated by the first read-write open, in one transaction: version 1 gets
// the two record tables; versions 1 and 2 get the co-moment columns' names (they were called
// cov_*, for values that were always the co-moment); versions 1 to 3 get the checksum columns,
// filled for the rows they hold (row_checksum.h); versions 1 to 4 get captures.superseded_by
// (NULL: no capture of theirs was ever taken again); versions 1 to 5 get session.uuid (a new
// random one) and the lab_certificates table; versions 1 to 6 get captures.sensor and
// results.sensor (0: every capture and result is the one sensor's) and the sensors table, the
// captures table rebuilt for its UNIQUE (step_id, sensor) and its checksums computed anew
// (session_schema.cpp says how damage is kept). A read-only open of an older file reads it
// as it is (a version-1 file has no records; rows
// of a file older than version 4 have no checksum to verify; one older than version 6 has no
// uuid and was never published; one older than version 7 holds one sensor, sensor 0).
//
// NaN (no radius, no temperature) is stored as NULL. Times are UTC ISO 8601 text.
#pragma once

#include <string>

#include "accelcal/session/detail/sqlite_db.h"

namespace accelcal::detail {

inline constexpr int kSessionSchemaVersion = 7;
inline constexpr int kSessionApplicationId = 0x41434331;  // "ACC1"

// Creates the tables and the session row in a new, empty database (one transaction).
void CreateSessionSchema(SqliteDb& db, const std::string& name, const std::string& procedure,
                         const std::string& source);
// True when the database has no tables yet (a file just created).
bool IsEmptyDatabase(SqliteDb& db);
// Throws accelcal::Error when the file is not an accelcal session or has a schema version this
// build does not know ("written by a newer accelcal"). `wal_missing` (WalFileMissing, taken
// before the database was opened: SQLite may create an empty -wal) turns "not an accelcal
// session" into what is wrong: the -wal file holding its latest changes is not beside it.
void CheckSessionSchema(SqliteDb& db, bool wal_missing);

// True when the file at `path` is in WAL mode (its header says so) and has no "-wal" beside it.
bool WalFileMissing(const std::string& path);
// Brings a session of an older known version up to kSessionSchemaVersion (read-write opens;
// one transaction; nothing to do when it is current).
void MigrateSessionSchema(SqliteDb& db);
// True when the database has the table `name` (a version-1 file has no record tables).
bool HasTable(SqliteDb& db, const std::string& name);

}  // namespace accelcal::detail
