// What a wizard session records as it goes, so that nothing accepted is ever lost and an
// interrupted session resumes where it stopped. The SQLite store (session_store.h) is the real
// implementation; MakeMemoryJournal() is for tests.
//
// Contract: every Record* / Append* call is durable when it returns (committed in its own
// transaction), so a kill -9 right after loses nothing it recorded. Step ids are the procedure's.
//
// Records (steps of kind "record": hours of samples) are not captures: they are appended in
// chunks (RecordChunk), each durable on its own, so an interruption loses at most the chunk
// being filled. A resumed record states the hole it has (RecordGap), committed together with
// the first chunk after it. Times of a record are on the record's clock: the source's t for
// the first run, then shifted so that the clock runs on across a restart (t of the first
// sample after a gap = t of the last one before it + the gap).
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/fixture.h"
#include "accelcal/session/session_inputs.h"

namespace accelcal {

struct JournalCapture {
  std::string step_id;
  Capture capture;  // with its raw samples
  // The journal step id of the capture that replaced this one when its step was taken again (a
  // redo: RecordRedoCapture); empty while it is current. A superseded capture stays in the
  // session but is out of the fit, the report and the exports (CurrentCaptures).
  std::string superseded_by;
  // Which of the session's sensors took it (issue 31): 0, the first (a one-sensor session's).
  int sensor = 0;

  bool superseded() const { return !superseded_by.empty(); }
};

// One sensor's capture of a pose that several sensors took at once.
struct SensorCapture {
  int sensor = 0;  // index into the session's sensors
  Capture capture;
};

// The captures of `all` that are not superseded, in the same order.
std::vector<JournalCapture> CurrentCaptures(std::vector<JournalCapture> all);

// A stored capture that fails its check on read (its checksum does not match what it holds, or
// its samples do not decode): the file was damaged after it was written. It is left out of
// Captures(); DamagedCaptures() names it.
struct DamagedCapture {
  std::string step_id;
  std::string label;    // as stored (it may be the damaged part)
  std::string problem;  // "its checksum does not match what it holds"
  int sensor = 0;       // whose (the session's sensors)

  // "the capture of step 'face_3' (\"Z up\") is damaged in the session file (its checksum
  // does not match what it holds): left out"
  std::string Describe() const;
};

// A hole in a record: no samples between t_start_s (the last sample before it) and t_end_s (the
// first sample after it), on the record's clock, s.
struct RecordGap {
  double t_start_s = 0.0;
  double t_end_s = 0.0;
  std::string reason;  // e.g. "resumed after interruption"

  double duration_s() const { return t_end_s - t_start_s; }
};

// A stretch of a record's samples, stored as one unit.
struct RecordChunk {
  long index = 0;               // 0, 1, 2, ... in recording order, without holes
  std::vector<Sample> samples;  // non-empty; t on the record's clock, increasing
  // When the chunk was complete, s since the Unix epoch on the computer's clock (a resumed
  // record measures its gap from it).
  double wall_end_s = 0.0;
  std::optional<RecordGap> gap_before;  // the hole just before this chunk (after a resume)
  // Only on the last chunk read back: the hole after it when the record's last chunks are
  // damaged (there is no chunk after them to carry it as gap_before).
  std::optional<RecordGap> gap_after;
};

// What a record holds so far, without its samples (cheap: for resuming and listings).
struct RecordSummary {
  long num_chunks = 0;
  long num_samples = 0;
  double t_first_s = kNaN;  // first sample, record clock, s; NaN when there is none
  double t_last_s = kNaN;   // last sample, s
  double last_wall_end_s = kNaN;  // wall_end_s of the last chunk
  long num_gaps = 0;
  double gaps_s = 0.0;      // sum of the gaps' durations, s

  // From the first sample to the last, gaps included, s (0 when empty).
  double span_s() const { return num_samples > 0 ? t_last_s - t_first_s : 0.0; }
  // The part of the span that has samples, s.
  double recorded_s() const { return span_s() - gaps_s; }
};

class SessionJournal {
 public:
  virtual ~SessionJournal() = default;

  // The operator's answer `value` to `key` at step `step_id` (a later one replaces it).
  virtual void RecordInput(const std::string& step_id, const std::string& key,
                           const std::string& value) = 0;
  // An accepted capture for `step_id`. A step has at most one accepted capture: recording a
  // second for the same step throws accelcal::Error (no duplicates after a resume).
  virtual void RecordCapture(const std::string& step_id, const Capture& capture) = 0;
  // A redo: `capture` recorded for `step_id` and the capture recorded under
  // `superseded_step_id` marked superseded by it, in one transaction (a kill between the two
  // cannot leave both current). Throws accelcal::Error as RecordCapture does, and when
  // `superseded_step_id` has no capture or one already superseded (nothing is recorded then).
  virtual void RecordRedoCapture(const std::string& step_id, const Capture& capture,
                                 const std::string& superseded_step_id) = 0;
  // --- Several sensors in one session (issue 31). A one-sensor session never calls these: its
  // one sensor is sensor 0, and Captures() is its captures. ---
  // The session's sensors (a fixture: serials, mountings, links), recorded before the first
  // capture of any sensor but the first. Recording the same again is a no-op (a resume); other
  // sensors throw accelcal::Error (a session's sensors never change under its captures).
  virtual void RecordSensors(const Fixture& sensors);
  // What RecordSensors recorded; nullopt: a one-sensor session (every older one).
  virtual std::optional<Fixture> Sensors() const { return std::nullopt; }
  // One pose's captures of several sensors for `step_id`, in one transaction: all are
  // recorded, or none. Throws accelcal::Error as RecordCapture does (a sensor's second capture
  // of the step), and for a sensor the session does not have.
  virtual void RecordSensorCaptures(const std::string& step_id,
                                    const std::vector<SensorCapture>& captures);
  // A redo of a pose for several sensors: every sensor's capture of `superseded_step_id`
  // marked superseded and `captures` recorded for `step_id`, in one transaction (as
  // RecordRedoCapture, which is this for sensor 0 alone).
  virtual void RecordSensorRedoCaptures(const std::string& step_id,
                                        const std::vector<SensorCapture>& captures,
                                        const std::string& superseded_step_id);
  // Sensor `sensor`'s captures, in recording order (Captures() is sensor 0's).
  virtual std::vector<JournalCapture> SensorCaptures(int sensor) const;
  // Sensor `sensor`'s result (RecordResult and Result are sensor 0's). A later one replaces it.
  virtual void RecordSensorResult(int sensor, const std::string& calibration_json);
  virtual std::optional<std::string> SensorResult(int sensor) const;
  // How many results sensor `sensor` has, its latest included (ResultCount is sensor 0's).
  virtual int SensorResultCount(int sensor) const { return SensorResult(sensor) ? 1 : 0; }

  // A step finished without a capture (leveling done, skipped, ...), with its outcome.
  virtual void RecordStepDone(const std::string& step_id, const std::string& outcome) = 0;
  // The session's result (the calibration file's JSON). A later one becomes the result; the
  // earlier ones stay (a history: ResultCount; `accelcal refit`).
  // `calibration_json` is the calibration file's text (io/calibration_file.h writes and reads it;
  // the journal stores it as it is).
  virtual void RecordResult(const std::string& calibration_json) = 0;
  // The session is finished (its procedure completed); durable when it returns.
  virtual void MarkDone() = 0;

  // The next chunk of the record of `step_id`, with the gap before it when it has one, in one
  // transaction. Throws accelcal::Error when chunk.index is not the next one (a chunk is never
  // replaced, never skipped), when it is empty, or when its samples do not come after the
  // record's last one.
  virtual void AppendRecordChunk(const std::string& step_id, const RecordChunk& chunk) = 0;

  // What was recorded (for resuming and for reports), in the order recorded: sensor 0's
  // captures (every capture of a one-sensor session; SensorCaptures for the others). A capture
  // that fails its check on read (session_store.h) is left out here and named (whichever its
  // sensor) by DamagedCaptures().
  virtual std::vector<JournalCapture> Captures() const = 0;
  virtual std::vector<DamagedCapture> DamagedCaptures() const { return {}; }
  virtual SessionInputs Inputs() const = 0;
  virtual std::map<std::string, std::string> DoneSteps() const = 0;  // step id -> outcome
  virtual std::optional<std::string> Result() const = 0;  // the latest RecordResult text
  // How many results were recorded, the latest included (0: none); sensor 0's in a session of
  // several sensors (each fit round records one per sensor).
  virtual int ResultCount() const { return Result() ? 1 : 0; }
  // The record of `step_id` so far (an empty summary when it has none).
  virtual RecordSummary RecordSummaryOf(const std::string& step_id) const = 0;
  // Calls `visit` with each chunk of the record of `step_id`, in order (one chunk in memory at
  // a time: a 12-hour record at 100 Hz is 170 MB of samples). A chunk that fails its check on
  // read is left out: the next chunk carries the hole as its gap_before, whose reason names the
  // damage (so every reader of a record sees it as a gap, never as data); damaged last chunks
  // are the last good chunk's gap_after.
  virtual void VisitRecordChunks(const std::string& step_id,
                                 const std::function<void(const RecordChunk&)>& visit) const = 0;
  // The steps that have record chunks, in the order their first chunk was recorded.
  virtual std::vector<std::string> RecordSteps() const = 0;
};

// A whole record read back: the samples in order and the gaps.
struct JournalRecord {
  std::vector<Sample> samples;
  std::vector<RecordGap> gaps;
};
// Throws accelcal::Error naming the damage when the record has chunks but none of them can be
// read (every one damaged in the session file): never an empty record read as if it were one.
JournalRecord ReadRecord(const SessionJournal& journal, const std::string& step_id);
// The check ReadRecord makes, for readers that visit the chunks themselves: throws
// accelcal::Error when `step_id` holds chunks and `samples_read` of them could be read is 0.
void CheckRecordReadable(const SessionJournal& journal, const std::string& step_id, long samples_read);

// The checks every journal makes on AppendRecordChunk against what it holds; throws
// accelcal::Error naming the step (shared by the store and the memory journal).
void CheckRecordChunk(const std::string& step_id, const RecordChunk& chunk,
                      const RecordSummary& so_far);
// "drift: 12 h 0 min recorded over 12 h 0 min, 2 gaps (14 s); noise: ..." for every record of
// the journal; empty when it has none.
std::string DescribeRecords(const SessionJournal& journal);
// `so_far` with `chunk` appended.
RecordSummary AddToSummary(RecordSummary so_far, const RecordChunk& chunk);

// The session's sensors: Sensors(), or for a one-sensor session its one sensor, named by the
// device input (kDeviceKey) when it has one.
Fixture SessionSensors(const SessionJournal& journal);

std::unique_ptr<SessionJournal> MakeMemoryJournal();

}  // namespace accelcal
