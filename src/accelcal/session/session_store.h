// The session store: a SessionJournal kept in one SQLite file per session (the file IS the
// session). Schema: detail/session_schema.h.
//
// Durability: WAL journal with synchronous=FULL, and every Record* is one transaction that has
// committed when the call returns, so a kill -9 (or a power loss) at any instant loses nothing
// that was recorded; a transaction cut short leaves no trace.
//
// Integrity: every capture and record chunk carries a checksum of what it holds (schema version
// 4, detail/row_checksum.h), written with it and verified on every read: a row damaged in the
// file afterwards is left out and named (DamagedCaptures(), a record's gap), never read as data.
//
// One writer: a read-write Open takes an advisory lock (detail/session_lock.h) that the OS
// releases when the process dies, so a second wizard is refused while the first lives and a
// session left by a killed one opens at once. Read-only opens take no lock and work while a
// wizard writes.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "accelcal/session/session_journal.h"

namespace accelcal {

namespace detail {
class SqliteDb;
class SessionLock;
}  // namespace detail

struct SessionOpenOptions {
  // Open without writing and without the lock (sessions, export, report). The file must exist.
  bool read_only = false;
  // Read-write only: create the session when the file does not exist (else it must exist).
  bool create_if_missing = true;
  // Stored when the session is created (ignored when it exists): the procedure's name and the
  // sample source's spec (e.g. "sim", "serial:/dev/ttyUSB0").
  std::string procedure;
  std::string source;

  // Empty when valid, else the problem.
  std::string Validate() const;
};

enum class SessionState { kOpen, kDone };
std::string_view SessionStateToString(SessionState state);       // "open" / "done"
std::optional<SessionState> StringToSessionState(std::string_view text);

struct SessionInfo {
  std::string path;
  std::string name;          // the file's stem
  std::string procedure;
  std::string source;
  std::string device;        // serial, from the input key "device"; may be empty
  std::string operator_name; // from the input key "operator"; may be empty
  std::string created_utc;   // ISO 8601
  std::string updated_utc;
  SessionState state = SessionState::kOpen;
  // The session's identity (base/uuid.h), the same in every copy of the file: what a lab's store
  // knows it by. Empty for a file older than schema version 6 opened read-only (a writer gives
  // it one when it migrates the file).
  std::string uuid;
  long num_lab_certificates = 0;  // sensors whose calibration a lab's store has numbered
  long num_captures = 0;
  long num_inputs = 0;
  long num_done_steps = 0;
  bool has_result = false;
};

// The certificate number a lab's store assigned to one sensor's calibration when the session was
// published there (app/lab_publish.h, docs/lab.md), written back into the session.
struct LabCertificateMark {
  int sensor_index = 0;            // 0 while a session holds one sensor
  std::string certificate_number;  // the lab's, e.g. "LAB-000042"
  std::string lab;                 // which store numbered it (LabStore::Identity())
  std::string published_utc;       // ISO 8601
};

// The input keys that also fill the session's device and operator (session_inputs.h), at
// whichever step records them ("session" by convention; the wizard asks at "welcome").
inline constexpr const char* kSessionStep = "session";
inline constexpr const char* kDeviceKey = welcome_key::kDevice;
inline constexpr const char* kOperatorKey = welcome_key::kOperator;

class SessionStore final : public SessionJournal {
 public:
  // Opens (or creates) the session at `path`. Throws accelcal::Error: another accelcal holds it
  // ("session PATH is open in another accelcal (pid N)"), it is missing (read-only or
  // !create_if_missing), not an accelcal session, or of a newer schema version. A read-write
// open migrates an older schema (detail/session_schema.h); a read-only one reads it as it is.
  static std::unique_ptr<SessionStore> Open(const std::string& path, const SessionOpenOptions& options);
  ~SessionStore() override;

  void RecordInput(const std::string& step_id, const std::string& key,
                   const std::string& value) override;
  void RecordCapture(const std::string& step_id, const Capture& capture) override;
  void RecordRedoCapture(const std::string& step_id, const Capture& capture,
                         const std::string& superseded_step_id) override;
  void RecordStepDone(const std::string& step_id, const std::string& outcome) override;
  void RecordResult(const std::string& calibration_json) override;
  void AppendRecordChunk(const std::string& step_id, const RecordChunk& chunk) override;
  void RecordSensors(const Fixture& sensors) override;
  std::optional<Fixture> Sensors() const override;
  void RecordSensorCaptures(const std::string& step_id,
                            const std::vector<SensorCapture>& captures) override;
  void RecordSensorRedoCaptures(const std::string& step_id, const std::vector<SensorCapture>& captures,
                                const std::string& superseded_step_id) override;
  std::vector<JournalCapture> SensorCaptures(int sensor) const override;
  void RecordSensorResult(int sensor, const std::string& calibration_json) override;
  std::optional<std::string> SensorResult(int sensor) const override;
  int SensorResultCount(int sensor) const override;

  std::vector<JournalCapture> Captures() const override;
  std::vector<DamagedCapture> DamagedCaptures() const override;
  SessionInputs Inputs() const override;
  std::map<std::string, std::string> DoneSteps() const override;
  std::optional<std::string> Result() const override;
  int ResultCount() const override;
  RecordSummary RecordSummaryOf(const std::string& step_id) const override;
  void VisitRecordChunks(const std::string& step_id,
                         const std::function<void(const RecordChunk&)>& visit) const override;
  std::vector<std::string> RecordSteps() const override;

  SessionInfo Info() const;
  // The lab's certificate numbers of this session, by sensor index; none until it is published.
  std::vector<LabCertificateMark> LabCertificates() const;
  // Writes `mark` back into the session, in one transaction. The session's updated time is left
  // as it is (publishing changes nothing the session recorded, and the report dates the
  // calibration by it). The same mark again changes nothing; another number for a sensor that
  // has one throws accelcal::Error: a number written back is never replaced.
  void RecordLabCertificate(const LabCertificateMark& mark);
  // The session is finished (state 'done'); one transaction.
  void MarkDone() override;
  const std::string& path() const { return path_; }

 private:
  SessionStore(std::string path, std::unique_ptr<detail::SessionLock> lock,
               std::unique_ptr<detail::SqliteDb> db, bool read_only);
  void RequireWritable() const;
  // Records `captures` for `step_id` and, unless empty, supersedes every capture of
  // `superseded_step_id`, in one transaction.
  void RecordSensorCapturesSuperseding(const std::string& step_id,
                                       const std::vector<SensorCapture>& captures,
                                       const std::string& superseded_step_id);

  std::string path_;
  std::unique_ptr<detail::SessionLock> lock_;  // owned; null when read-only. Released after db_.
  std::unique_ptr<detail::SqliteDb> db_;       // owned
  bool read_only_ = false;
};

}  // namespace accelcal
