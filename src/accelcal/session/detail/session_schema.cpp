#include "accelcal/session/detail/session_schema.h"

#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/base/utc_time.h"
#include "accelcal/base/uuid.h"
#include "accelcal/session/detail/row_checksum.h"

namespace accelcal::detail {
namespace {

constexpr const char* kTables = R"sql(
CREATE TABLE session (
  id INTEGER PRIMARY KEY CHECK (id = 1),
  name TEXT NOT NULL, procedure TEXT NOT NULL, source TEXT NOT NULL,
  device TEXT NOT NULL DEFAULT '', operator TEXT NOT NULL DEFAULT '',
  created_utc TEXT NOT NULL, updated_utc TEXT NOT NULL,
  state TEXT NOT NULL CHECK (state IN ('open', 'done')), uuid TEXT);
CREATE TABLE devices (serial TEXT PRIMARY KEY, first_seen_utc TEXT NOT NULL);
CREATE TABLE captures (
  seq INTEGER PRIMARY KEY AUTOINCREMENT,
  step_id TEXT NOT NULL,
  capture_id INTEGER NOT NULL, kind TEXT NOT NULL CHECK (kind IN ('static', 'turntable')),
  label TEXT NOT NULL, radius_m REAL, rpm REAL, up_axis TEXT, rejection_reason TEXT NOT NULL,
  n INTEGER NOT NULL,
  mean_x_counts REAL, mean_y_counts REAL, mean_z_counts REAL,
  comoment_xx_counts2 REAL, comoment_xy_counts2 REAL, comoment_xz_counts2 REAL,
  comoment_yy_counts2 REAL, comoment_yz_counts2 REAL, comoment_zz_counts2 REAL,
  t_first_s REAL, t_last_s REAL, mean_temp_c REAL,
  samples BLOB NOT NULL, recorded_utc TEXT NOT NULL, checksum INTEGER, superseded_by TEXT,
  sensor INTEGER NOT NULL DEFAULT 0 CHECK (sensor >= 0), UNIQUE (step_id, sensor));
CREATE TABLE sensors (
  sensor INTEGER PRIMARY KEY CHECK (sensor >= 0), serial TEXT NOT NULL UNIQUE,
  sensor_to_plate TEXT NOT NULL, offset_m TEXT NOT NULL, source TEXT NOT NULL,
  fixture_name TEXT NOT NULL, recorded_utc TEXT NOT NULL);
CREATE TABLE inputs (step_id TEXT NOT NULL, key TEXT NOT NULL, value TEXT NOT NULL,
  recorded_utc TEXT NOT NULL, PRIMARY KEY (step_id, key));
CREATE TABLE steps_done (step_id TEXT PRIMARY KEY, outcome TEXT NOT NULL, recorded_utc TEXT NOT NULL);
CREATE TABLE results (seq INTEGER PRIMARY KEY AUTOINCREMENT, calibration_json TEXT NOT NULL,
  recorded_utc TEXT NOT NULL, sensor INTEGER NOT NULL DEFAULT 0 CHECK (sensor >= 0));
)sql";

// (The checksum columns came in version 4: MigrateToChecksums adds them to older files.)

// Added in version 2: the chunks and gaps of record steps.
constexpr const char* kRecordTables = R"sql(
CREATE TABLE record_chunks (
  step_id TEXT NOT NULL, chunk_index INTEGER NOT NULL CHECK (chunk_index >= 0),
  n INTEGER NOT NULL CHECK (n > 0), t_first_s REAL NOT NULL, t_last_s REAL NOT NULL,
  wall_end_s REAL NOT NULL, samples BLOB NOT NULL, recorded_utc TEXT NOT NULL, checksum INTEGER,
  PRIMARY KEY (step_id, chunk_index));
CREATE TABLE record_gaps (
  step_id TEXT NOT NULL, before_chunk INTEGER NOT NULL, t_start_s REAL NOT NULL,
  t_end_s REAL NOT NULL, reason TEXT NOT NULL, recorded_utc TEXT NOT NULL,
  PRIMARY KEY (step_id, before_chunk));
)sql";

// Added in version 6: what a lab's store assigned when the session was published there.
constexpr const char* kLabCertificatesTable = R"sql(
CREATE TABLE lab_certificates (
  sensor_index INTEGER PRIMARY KEY CHECK (sensor_index >= 0),
  certificate_number TEXT NOT NULL, lab TEXT NOT NULL, published_utc TEXT NOT NULL);
)sql";

// Version 3: the capture statistics' second moments are named for what they hold, the co-moment
// sum (x - mean)(y - mean) (versions 1 and 2 called it cov_*; the values are unchanged).
constexpr const char* kRenameComoments = R"sql(
ALTER TABLE captures RENAME COLUMN cov_xx_counts2 TO comoment_xx_counts2;
ALTER TABLE captures RENAME COLUMN cov_xy_counts2 TO comoment_xy_counts2;
ALTER TABLE captures RENAME COLUMN cov_xz_counts2 TO comoment_xz_counts2;
ALTER TABLE captures RENAME COLUMN cov_yy_counts2 TO comoment_yy_counts2;
ALTER TABLE captures RENAME COLUMN cov_yz_counts2 TO comoment_yz_counts2;
ALTER TABLE captures RENAME COLUMN cov_zz_counts2 TO comoment_zz_counts2;
)sql";

// Version 4: a checksum per capture and per record chunk (row_checksum.h), computed here for
// the rows an older accelcal wrote. (Tables created by this build's migration from version 1
// already have the column.)
void MigrateToChecksums(SqliteDb& db) {
  // A captures table made by this build already has the sensor (version 7), whose checksum
  // covers it.
  const char* capture_columns =
      HasColumn(db, "captures", "sensor") ? kCaptureChecksumColumns : kCaptureChecksumColumnsV4;
  for (const auto& [table, columns] :
       {std::pair{"captures", capture_columns}, std::pair{"record_chunks", kChunkChecksumColumns}}) {
    if (!HasColumn(db, table, "checksum"))
      db.Exec(fmt::format("ALTER TABLE {} ADD COLUMN checksum INTEGER", table));
    StoreAllRowChecksums(db, table, columns);
  }
}

// Version 5: a capture taken again (a redo) is kept, marked superseded by the step id of the
// capture that replaced it (NULL: current). Older files have no redone capture: all NULL.
void MigrateToSuperseded(SqliteDb& db) {
  if (!HasColumn(db, "captures", "superseded_by"))
    db.Exec("ALTER TABLE captures ADD COLUMN superseded_by TEXT");
}

// Version 6: the session's identity (a random UUID: a session made before has none, so it gets
// one now, once: every later open reads the same) and the lab's certificate numbers.
void MigrateToLabIdentity(SqliteDb& db) {
  if (!HasColumn(db, "session", "uuid")) db.Exec("ALTER TABLE session ADD COLUMN uuid TEXT");
  SqliteStatement(db, "UPDATE session SET uuid = ? WHERE uuid IS NULL").Bind(1, NewRandomUuid()).Run();
  if (!HasTable(db, "lab_certificates")) db.Exec(kLabCertificatesTable);
}

// Version 7 (issue 31): a session holds several sensors. Each capture names its sensor (0: the
// first; every capture of an older file is its one sensor's), the step's uniqueness becomes
// (step_id, sensor), and the table `sensors` lists them (empty: one sensor, the session's
// device). SQLite cannot change a UNIQUE constraint in place: the table is rebuilt, in the
// migration's transaction. The checksum now covers the sensor too: it is computed anew for the
// rows whose version-4 checksum holds, and a row that was already damaged keeps no checksum
// (read as damaged, as before), so the migration never blesses damage.
constexpr const char* kCapturesV7 = R"sql(
CREATE TABLE captures_v7 (
  seq INTEGER PRIMARY KEY AUTOINCREMENT,
  step_id TEXT NOT NULL,
  capture_id INTEGER NOT NULL, kind TEXT NOT NULL CHECK (kind IN ('static', 'turntable')),
  label TEXT NOT NULL, radius_m REAL, rpm REAL, up_axis TEXT, rejection_reason TEXT NOT NULL,
  n INTEGER NOT NULL,
  mean_x_counts REAL, mean_y_counts REAL, mean_z_counts REAL,
  comoment_xx_counts2 REAL, comoment_xy_counts2 REAL, comoment_xz_counts2 REAL,
  comoment_yy_counts2 REAL, comoment_yz_counts2 REAL, comoment_zz_counts2 REAL,
  t_first_s REAL, t_last_s REAL, mean_temp_c REAL,
  samples BLOB NOT NULL, recorded_utc TEXT NOT NULL, checksum INTEGER, superseded_by TEXT,
  sensor INTEGER NOT NULL DEFAULT 0 CHECK (sensor >= 0), UNIQUE (step_id, sensor));
CREATE TABLE sensors (
  sensor INTEGER PRIMARY KEY CHECK (sensor >= 0), serial TEXT NOT NULL UNIQUE,
  sensor_to_plate TEXT NOT NULL, offset_m TEXT NOT NULL, source TEXT NOT NULL,
  fixture_name TEXT NOT NULL, recorded_utc TEXT NOT NULL);
)sql";

void MigrateToSensors(SqliteDb& db) {
  if (!HasColumn(db, "results", "sensor"))
    db.Exec("ALTER TABLE results ADD COLUMN sensor INTEGER NOT NULL DEFAULT 0 CHECK (sensor >= 0)");
  if (HasColumn(db, "captures", "sensor")) return;
  std::vector<std::int64_t> damaged;
  {
    SqliteStatement rows(db, fmt::format("SELECT seq, {}, checksum FROM captures",
                                         kCaptureChecksumColumnsV4));
    while (rows.Step())
      if (!ChecksumProblem(rows, 1, kCaptureChecksumColumnCountV4,
                           1 + kCaptureChecksumColumnCountV4).empty())
        damaged.push_back(rows.ColumnInt(0));
  }
  db.Exec(kCapturesV7);
  db.Exec(fmt::format("INSERT INTO captures_v7 (seq, {0}, checksum, superseded_by, sensor) "
                      "SELECT seq, {0}, checksum, superseded_by, 0 FROM captures",
                      kCaptureChecksumColumnsV4));
  db.Exec("DROP TABLE captures; ALTER TABLE captures_v7 RENAME TO captures");
  StoreAllRowChecksums(db, "captures", kCaptureChecksumColumns);
  for (const std::int64_t seq : damaged)
    SqliteStatement(db, "UPDATE captures SET checksum = NULL WHERE seq = ?").Bind(1, seq).Run();
}

}  // namespace

bool IsEmptyDatabase(SqliteDb& db) {
  // The first read tells a file that is not SQLite at all ("file is not a database").
  try {
    return db.QueryInt("SELECT count(*) FROM sqlite_schema") == 0;
  } catch (const Error& e) {
    throw Error(fmt::format("{} is not an accelcal session ({})", db.path(), e.what()));
  }
}

void CreateSessionSchema(SqliteDb& db, const std::string& name, const std::string& procedure,
                         const std::string& source) {
  SqliteTransaction transaction(db);
  db.Exec(kTables);
  db.Exec(kRecordTables);
  db.Exec(kLabCertificatesTable);
  const std::string now = UtcNowIso8601();
  SqliteStatement insert(db,
                         "INSERT INTO session (id, name, procedure, source, created_utc, "
                         "updated_utc, state, uuid) VALUES (1, ?, ?, ?, ?, ?, 'open', ?)");
  insert.Bind(1, name).Bind(2, procedure).Bind(3, source).Bind(4, now).Bind(5, now)
      .Bind(6, NewRandomUuid()).Run();
  db.Exec(fmt::format("PRAGMA application_id = {}; PRAGMA user_version = {}",
                      kSessionApplicationId, kSessionSchemaVersion));
  transaction.Commit();
}

namespace {

// A session file in WAL mode (bytes 18 and 19 of its header are 2, sqlite.org/fileformat.html
// section 1.3.3) whose "-wal" file is not beside it: it was copied without it, or its writer
// was killed and the -wal lost. Its latest changes (all of it, for a new session) are there.
void ThrowIfWalMissing(const std::string& path, bool wal_missing) {
  if (wal_missing)
    throw Error(fmt::format("session {} is incomplete: its latest changes are in {}-wal, which is not "
                            "beside it (copied without it, or lost after its program was killed); "
                            "copy {}-wal next to it",
                            path, path, std::filesystem::path(path).filename().string()));
}

}  // namespace

bool WalFileMissing(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char header[20] = {};
  in.read(header, sizeof header);
  const bool wal_mode = in.gcount() == sizeof header && header[18] == 2 && header[19] == 2;
  return wal_mode && !std::filesystem::exists(path + "-wal");
}

void CheckSessionSchema(SqliteDb& db, bool wal_missing) {
  IsEmptyDatabase(db);  // throws for a file that is not SQLite
  const std::int64_t application_id = db.QueryInt("PRAGMA application_id");
  const std::int64_t version = db.QueryInt("PRAGMA user_version");
  if (application_id != kSessionApplicationId) ThrowIfWalMissing(db.path(), wal_missing);
  if (application_id != kSessionApplicationId)
    throw Error(fmt::format("{} is not an accelcal session (a SQLite file of another program)",
                            db.path()));
  if (version > kSessionSchemaVersion)
    throw Error(fmt::format("session {} has schema version {}, newer than this accelcal reads "
                            "({}): use a newer accelcal", db.path(), version, kSessionSchemaVersion));
  if (version < 1)
    throw Error(fmt::format("session {} has an unknown schema version {}", db.path(), version));
}

bool HasTable(SqliteDb& db, const std::string& name) {
  SqliteStatement query(db, "SELECT 1 FROM sqlite_schema WHERE type = 'table' AND name = ?");
  query.Bind(1, name);
  return query.Step();
}

void MigrateSessionSchema(SqliteDb& db) {
  SqliteTransaction transaction(db);
  const std::int64_t version = db.QueryInt("PRAGMA user_version");
  if (version >= kSessionSchemaVersion) return;  // rolled back: nothing was written
  if (version < 2 && !HasTable(db, "record_chunks")) db.Exec(kRecordTables);
  if (version < 3) db.Exec(kRenameComoments);
  if (version < 4) MigrateToChecksums(db);
  if (version < 5) MigrateToSuperseded(db);
  if (version < 6) MigrateToLabIdentity(db);
  if (version < 7) MigrateToSensors(db);
  db.Exec(fmt::format("PRAGMA user_version = {}", kSessionSchemaVersion));
  transaction.Commit();
}

}  // namespace accelcal::detail
