// The wizard's in-memory model of its session: what the journal held when the wizard started,
// read once, plus everything recorded since. Every write goes to the journal first (durable when
// it returns, as the journal's contract says) and then to the model, so the wizard reads its own
// state from memory and never back from the store. The one exception is a record's samples
// (hours of them, too many to hold): VisitRecordChunks reads them back from the journal.
//
// Retakes: a capture found wanting after it was accepted (the noise floor it was judged with
// proved too high: noise_floor_guard.h) is marked left out (input "left_out ID" of its step,
// the reason as value) and its step is captured again, recorded under the journal step id
// "STEP#2", "STEP#3", ... (the journal keeps one capture per step id, and never replaces one).
// StepRecorded and CaptureOf look through the marks: a step is recorded when it has a capture
// that is not left out.
//
// Redo: the technician takes an accepted capture again (b on a later step); the new one is
// recorded the same way ("STEP#2", ...) and the old one marked superseded by it in the journal
// (RecordRedoCapture, one transaction). A superseded capture is never the step's capture and
// never goes into the fit (CurrentCaptures).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "accelcal/session/session_journal.h"

namespace accelcal {

class SessionModel final : public SessionJournal {
 public:
  // Borrows `journal` (it must outlive the model) and reads it once.
  explicit SessionModel(SessionJournal& journal);

  void RecordInput(const std::string& step_id, const std::string& key,
                   const std::string& value) override;
  void RecordCapture(const std::string& step_id, const Capture& capture) override;
  void RecordRedoCapture(const std::string& step_id, const Capture& capture,
                         const std::string& superseded_step_id) override;
  void RecordStepDone(const std::string& step_id, const std::string& outcome) override;
  void RecordResult(const std::string& calibration_json) override;
  void MarkDone() override;
  void AppendRecordChunk(const std::string& step_id, const RecordChunk& chunk) override;

  // Copies, for the SessionJournal interface; the wizard reads the references below.
  std::vector<JournalCapture> Captures() const override { return captures_; }
  std::map<std::string, std::map<std::string, std::string>> Inputs() const override { return inputs_; }
  std::map<std::string, std::string> DoneSteps() const override { return done_; }
  std::optional<std::string> Result() const override { return result_; }
  int ResultCount() const override { return journal_.ResultCount(); }
  RecordSummary RecordSummaryOf(const std::string& step_id) const override;
  void VisitRecordChunks(const std::string& step_id,
                         const std::function<void(const RecordChunk&)>& visit) const override;
  std::vector<std::string> RecordSteps() const override { return record_steps_; }

  const std::vector<JournalCapture>& captures() const { return captures_; }
  const std::map<std::string, std::map<std::string, std::string>>& inputs() const { return inputs_; }
  const std::map<std::string, std::string>& done_steps() const { return done_; }
  // The accepted capture of procedure step `step_id` that is neither left out nor superseded
  // (the latest retake);
  // nullptr when it has none.
  const JournalCapture* CaptureOf(const std::string& step_id) const;
  // True when the step has such a capture or is done.
  bool StepRecorded(const std::string& step_id) const;
  // The journal step id the next capture of procedure step `step_id` is recorded under.
  std::string NextCaptureStepId(const std::string& step_id) const;
  // The procedure step a journal step id belongs to ("pose_mx#2" -> "pose_mx").
  static std::string ProcedureStepOf(const std::string& journal_step_id);
  // Why `c` is left out of the calibration (empty: it is not).
  std::string LeftOutReason(const JournalCapture& c) const;
  // Marks `c` left out with `reason` (durable); its step is to be captured again.
  void MarkLeftOut(const JournalCapture& c, const std::string& reason);

 private:
  SessionJournal& journal_;  // borrowed: outlives the model
  std::vector<JournalCapture> captures_;
  std::map<std::string, std::map<std::string, std::string>> inputs_;
  std::map<std::string, std::string> done_;
  std::optional<std::string> result_;
  const JournalCapture* ExactCapture(const std::string& journal_step_id) const;
  std::map<std::string, RecordSummary> records_;
  std::vector<std::string> record_steps_;
};

}  // namespace accelcal
