#include "accelcal/session/session_store.h"

#include <filesystem>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/session/detail/capture_rows.h"
#include "accelcal/session/detail/record_rows.h"
#include "accelcal/session/detail/row_checksum.h"
#include "accelcal/session/detail/sensor_rows.h"
#include "accelcal/session/detail/session_lock.h"
#include "accelcal/session/detail/session_schema.h"
#include "accelcal/session/detail/sqlite_db.h"
#include "accelcal/base/utc_time.h"

namespace accelcal {

using detail::SqliteStatement;
using detail::SqliteTransaction;

std::string SessionOpenOptions::Validate() const {
  if (read_only && (!procedure.empty() || !source.empty()))
    return "a read-only open cannot set the procedure or the source";
  return "";
}

std::string_view SessionStateToString(SessionState state) {
  return state == SessionState::kDone ? "done" : "open";
}

std::optional<SessionState> StringToSessionState(std::string_view text) {
  if (text == "open") return SessionState::kOpen;
  if (text == "done") return SessionState::kDone;
  return std::nullopt;
}

namespace {

void ConfigureWriter(detail::SqliteDb& db) {
  // WAL: readers (sessions, export, report) never block the wizard; FULL: each commit is
  // fsynced, so it survives a power loss as well as a kill -9.
  db.Exec("PRAGMA journal_mode = WAL; PRAGMA synchronous = FULL; PRAGMA foreign_keys = ON");
}

void TouchSession(detail::SqliteDb& db, const std::string& now) {
  SqliteStatement touch(db, "UPDATE session SET updated_utc = ? WHERE id = 1");
  touch.Bind(1, now).Run();
}

// The inputs that name the device and the operator (keys "device", "operator", at whichever
// step asks for them) also fill the session row (and devices).
void RecordSessionInput(detail::SqliteDb& db, const std::string& key, const std::string& value,
                        const std::string& now) {
  if (key == kDeviceKey) {
    SqliteStatement(db, "UPDATE session SET device = ? WHERE id = 1").Bind(1, value).Run();
    SqliteStatement(db, "INSERT OR IGNORE INTO devices (serial, first_seen_utc) VALUES (?, ?)")
        .Bind(1, value).Bind(2, now).Run();
  } else if (key == kOperatorKey) {
    SqliteStatement(db, "UPDATE session SET operator = ? WHERE id = 1").Bind(1, value).Run();
  }
}

std::string StemOf(const std::string& path) { return std::filesystem::path(path).stem().string(); }

}  // namespace

std::unique_ptr<SessionStore> SessionStore::Open(const std::string& path,
                                                 const SessionOpenOptions& options) {
  if (std::string e = options.Validate(); !e.empty()) throw Error("session options: " + e);
  const bool exists = std::filesystem::exists(path);
  if (!exists && (options.read_only || !options.create_if_missing))
    throw Error(fmt::format("no session at {}", path));
  // The lock comes first, so that two processes never create or check the schema at once.
  std::unique_ptr<detail::SessionLock> lock;
  if (!options.read_only) lock = std::make_unique<detail::SessionLock>(path);
  const bool wal_missing = exists && detail::WalFileMissing(path);
  auto db = std::make_unique<detail::SqliteDb>(path, options.read_only);
  // An empty database whose -wal is missing is a copy made while its writer ran, not a new
  // session: never create a schema over it (CheckSessionSchema says what is missing).
  if (!options.read_only && !wal_missing && detail::IsEmptyDatabase(*db)) {
    ConfigureWriter(*db);
    detail::CreateSessionSchema(*db, StemOf(path), options.procedure, options.source);
  } else {
    detail::CheckSessionSchema(*db, wal_missing);
    if (!options.read_only) {
      ConfigureWriter(*db);
      detail::MigrateSessionSchema(*db);
    }
  }
  return std::unique_ptr<SessionStore>(
      new SessionStore(path, std::move(lock), std::move(db), options.read_only));
}

SessionStore::SessionStore(std::string path, std::unique_ptr<detail::SessionLock> lock,
                           std::unique_ptr<detail::SqliteDb> db, bool read_only)
    : path_(std::move(path)), lock_(std::move(lock)), db_(std::move(db)), read_only_(read_only) {}

SessionStore::~SessionStore() {
  if (read_only_) return;
  // Back to a rollback journal on a clean close: the file then stands alone (no -wal/-shm
  // beside it, which read-only readers would otherwise recreate and leave). Best effort: it
  // fails harmlessly while a reader has the file open, and the next writer sets WAL again.
  try {
    db_->Exec("PRAGMA journal_mode = DELETE");
  } catch (const Error&) {
  }
}

void SessionStore::RequireWritable() const {
  if (read_only_) throw Error(fmt::format("session {} was opened read-only", path_));
}

void SessionStore::RecordInput(const std::string& step_id, const std::string& key,
                               const std::string& value) {
  RequireWritable();
  const std::string now = UtcNowIso8601();
  SqliteTransaction transaction(*db_);
  SqliteStatement(*db_, "INSERT OR REPLACE INTO inputs (step_id, key, value, recorded_utc) "
                        "VALUES (?, ?, ?, ?)")
      .Bind(1, step_id).Bind(2, key).Bind(3, value).Bind(4, now).Run();
  RecordSessionInput(*db_, key, value, now);
  TouchSession(*db_, now);
  transaction.Commit();
}

void SessionStore::RecordCapture(const std::string& step_id, const Capture& capture) {
  RequireWritable();
  const std::string now = UtcNowIso8601();
  SqliteTransaction transaction(*db_);
  detail::InsertCaptureRow(*db_, step_id, capture, now);
  TouchSession(*db_, now);
  transaction.Commit();
  // Move the committed pages from the -wal file into the session file itself, so a copy of the
  // file alone (made after a kill -9, without its -wal) still holds every accepted capture.
  // PASSIVE: never waits for a reader; what a reader blocks goes in at the next capture.
  db_->Exec("PRAGMA wal_checkpoint(PASSIVE)");
}

void SessionStore::RecordRedoCapture(const std::string& step_id, const Capture& capture,
                                     const std::string& superseded_step_id) {
  RequireWritable();
  const std::string now = UtcNowIso8601();
  SqliteTransaction transaction(*db_);
  detail::MarkCaptureRowSuperseded(*db_, superseded_step_id, step_id);
  detail::InsertCaptureRow(*db_, step_id, capture, now);
  TouchSession(*db_, now);
  transaction.Commit();
  db_->Exec("PRAGMA wal_checkpoint(PASSIVE)");  // as RecordCapture
}

void SessionStore::RecordStepDone(const std::string& step_id, const std::string& outcome) {
  RequireWritable();
  const std::string now = UtcNowIso8601();
  SqliteTransaction transaction(*db_);
  SqliteStatement(*db_, "INSERT OR REPLACE INTO steps_done (step_id, outcome, recorded_utc) "
                        "VALUES (?, ?, ?)")
      .Bind(1, step_id).Bind(2, outcome).Bind(3, now).Run();
  TouchSession(*db_, now);
  transaction.Commit();
}

void SessionStore::RecordResult(const std::string& calibration_json) {
  RecordSensorResult(0, calibration_json);
}

void SessionStore::RecordSensorResult(int sensor, const std::string& calibration_json) {
  RequireWritable();
  if (sensor < 0) throw Error(fmt::format("session {}: no sensor {}", path_, sensor));
  const std::string now = UtcNowIso8601();
  SqliteTransaction transaction(*db_);
  // Earlier results stay as history; Result() is the latest.
  SqliteStatement(*db_, "INSERT INTO results (calibration_json, recorded_utc, sensor) VALUES (?, ?, ?)")
      .Bind(1, calibration_json).Bind(2, now).Bind(3, sensor).Run();
  TouchSession(*db_, now);
  transaction.Commit();
}

void SessionStore::AppendRecordChunk(const std::string& step_id, const RecordChunk& chunk) {
  RequireWritable();
  const std::string now = UtcNowIso8601();
  SqliteTransaction transaction(*db_);
  detail::InsertRecordChunk(*db_, step_id, chunk, now);
  TouchSession(*db_, now);
  transaction.Commit();
}

RecordSummary SessionStore::RecordSummaryOf(const std::string& step_id) const {
  return detail::ReadRecordSummary(*db_, step_id);
}

void SessionStore::VisitRecordChunks(const std::string& step_id,
                                     const std::function<void(const RecordChunk&)>& visit) const {
  detail::VisitRecordRows(*db_, step_id, visit);
}

std::vector<std::string> SessionStore::RecordSteps() const { return detail::ReadRecordSteps(*db_); }

void SessionStore::MarkDone() {
  RequireWritable();
  const std::string now = UtcNowIso8601();
  SqliteTransaction transaction(*db_);
  SqliteStatement(*db_, "UPDATE session SET state = 'done' WHERE id = 1").Run();
  TouchSession(*db_, now);
  transaction.Commit();
}

std::vector<JournalCapture> SessionStore::Captures() const { return SensorCaptures(0); }

std::vector<JournalCapture> SessionStore::SensorCaptures(int sensor) const {
  if (sensor < 0) return {};
  return detail::ReadCaptureRows(*db_, sensor).intact;
}

std::vector<DamagedCapture> SessionStore::DamagedCaptures() const {
  return detail::ReadCaptureRows(*db_, -1).damaged;
}

void SessionStore::RecordSensors(const Fixture& sensors) {
  RequireWritable();
  const std::string now = UtcNowIso8601();
  SqliteTransaction transaction(*db_);
  detail::InsertSensorRows(*db_, sensors, now);
  TouchSession(*db_, now);
  transaction.Commit();
}

std::optional<Fixture> SessionStore::Sensors() const { return detail::ReadSensorRows(*db_); }

void SessionStore::RecordSensorCaptures(const std::string& step_id,
                                        const std::vector<SensorCapture>& captures) {
  RecordSensorCapturesSuperseding(step_id, captures, "");
}

void SessionStore::RecordSensorRedoCaptures(const std::string& step_id,
                                            const std::vector<SensorCapture>& captures,
                                            const std::string& superseded_step_id) {
  RecordSensorCapturesSuperseding(step_id, captures, superseded_step_id);
}

void SessionStore::RecordSensorCapturesSuperseding(const std::string& step_id,
                                                   const std::vector<SensorCapture>& captures,
                                                   const std::string& superseded_step_id) {
  RequireWritable();
  const std::size_t sensors = Sensors() ? Sensors()->sensors.size() : 1;
  for (const SensorCapture& c : captures)
    if (c.sensor < 0 || static_cast<std::size_t>(c.sensor) >= sensors)
      throw Error(fmt::format("session {} has {} sensor(s): no sensor {}", path_, sensors,
                              c.sensor + 1));
  const std::string now = UtcNowIso8601();
  SqliteTransaction transaction(*db_);
  if (!superseded_step_id.empty()) detail::MarkCaptureRowSuperseded(*db_, superseded_step_id, step_id);
  for (const SensorCapture& c : captures)
    detail::InsertCaptureRow(*db_, step_id, c.capture, now, c.sensor);
  TouchSession(*db_, now);
  transaction.Commit();
  db_->Exec("PRAGMA wal_checkpoint(PASSIVE)");  // as RecordCapture
}

SessionInputs SessionStore::Inputs() const {
  std::map<std::string, std::map<std::string, std::string>> out;
  SqliteStatement rows(*db_, "SELECT step_id, key, value FROM inputs");
  while (rows.Step()) out[rows.ColumnText(0)][rows.ColumnText(1)] = rows.ColumnText(2);
  return out;
}

std::map<std::string, std::string> SessionStore::DoneSteps() const {
  std::map<std::string, std::string> out;
  SqliteStatement rows(*db_, "SELECT step_id, outcome FROM steps_done");
  while (rows.Step()) out[rows.ColumnText(0)] = rows.ColumnText(1);
  return out;
}

std::optional<std::string> SessionStore::Result() const { return SensorResult(0); }

std::optional<std::string> SessionStore::SensorResult(int sensor) const {
  // A file older than version 7 read as it is: its results are its one sensor's.
  const bool by_sensor = detail::HasColumn(*db_, "results", "sensor");
  if (!by_sensor && sensor != 0) return std::nullopt;
  SqliteStatement row(*db_, by_sensor ? "SELECT calibration_json FROM results WHERE sensor = ? "
                                        "ORDER BY seq DESC LIMIT 1"
                                      : "SELECT calibration_json FROM results ORDER BY seq DESC LIMIT 1");
  if (by_sensor) row.Bind(1, sensor);
  if (!row.Step()) return std::nullopt;
  return row.ColumnText(0);
}

int SessionStore::ResultCount() const { return SensorResultCount(0); }

int SessionStore::SensorResultCount(int sensor) const {
  // A file older than version 7 read as it is: its results are its one sensor's.
  if (!detail::HasColumn(*db_, "results", "sensor"))
    return sensor == 0 ? static_cast<int>(db_->QueryInt("SELECT count(*) FROM results")) : 0;
  SqliteStatement count(*db_, "SELECT count(*) FROM results WHERE sensor = ?");
  count.Bind(1, sensor);
  count.Step();
  return static_cast<int>(count.ColumnInt(0));
}

SessionInfo SessionStore::Info() const {
  SessionInfo info;
  info.path = path_;
  SqliteStatement row(*db_, "SELECT name, procedure, source, device, operator, created_utc, "
                            "updated_utc, state FROM session WHERE id = 1");
  if (!row.Step()) throw Error(fmt::format("session {} is damaged: no session row", path_));
  info.name = row.ColumnText(0);
  info.procedure = row.ColumnText(1);
  info.source = row.ColumnText(2);
  info.device = row.ColumnText(3);
  info.operator_name = row.ColumnText(4);
  info.created_utc = row.ColumnText(5);
  info.updated_utc = row.ColumnText(6);
  info.state = StringToSessionState(row.ColumnText(7)).value_or(SessionState::kOpen);
  // (A file older than version 6, read as it is, has neither.)
  if (detail::HasColumn(*db_, "session", "uuid")) {
    SqliteStatement uuid(*db_, "SELECT coalesce(uuid, '') FROM session WHERE id = 1");
    if (uuid.Step()) info.uuid = uuid.ColumnText(0);
  }
  if (detail::HasTable(*db_, "lab_certificates"))
    info.num_lab_certificates = static_cast<long>(db_->QueryInt("SELECT count(*) FROM lab_certificates"));
  info.num_captures = static_cast<long>(db_->QueryInt("SELECT count(DISTINCT step_id) FROM captures"));
  info.num_inputs = static_cast<long>(db_->QueryInt("SELECT count(*) FROM inputs"));
  info.num_done_steps = static_cast<long>(db_->QueryInt("SELECT count(*) FROM steps_done"));
  info.has_result = db_->QueryInt("SELECT count(*) FROM results") > 0;
  return info;
}

std::vector<LabCertificateMark> SessionStore::LabCertificates() const {
  std::vector<LabCertificateMark> marks;
  if (!detail::HasTable(*db_, "lab_certificates")) return marks;  // older than version 6
  SqliteStatement rows(*db_, "SELECT sensor_index, certificate_number, lab, published_utc "
                             "FROM lab_certificates ORDER BY sensor_index");
  while (rows.Step())
    marks.push_back({static_cast<int>(rows.ColumnInt(0)), rows.ColumnText(1), rows.ColumnText(2),
                     rows.ColumnText(3)});
  return marks;
}

void SessionStore::RecordLabCertificate(const LabCertificateMark& mark) {
  RequireWritable();
  SqliteTransaction transaction(*db_);
  SqliteStatement held(*db_, "SELECT certificate_number, lab FROM lab_certificates WHERE sensor_index = ?");
  held.Bind(1, mark.sensor_index);
  if (held.Step()) {
    if (held.ColumnText(0) == mark.certificate_number) return;  // rolled back: nothing to write
    throw Error(fmt::format("session {} already holds certificate {} from {} for sensor {}; it is "
                            "not replaced by {}", path_, held.ColumnText(0), held.ColumnText(1),
                            mark.sensor_index, mark.certificate_number));
  }
  SqliteStatement(*db_, "INSERT INTO lab_certificates (sensor_index, certificate_number, lab, "
                        "published_utc) VALUES (?, ?, ?, ?)")
      .Bind(1, mark.sensor_index).Bind(2, mark.certificate_number).Bind(3, mark.lab)
      .Bind(4, mark.published_utc).Run();
  transaction.Commit();
}

}  // namespace accelcal
