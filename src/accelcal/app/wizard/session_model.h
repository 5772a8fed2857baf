// The wizard's in-memory model of its session: what the journal held when the wizard started,
// read once, plus everything recorded since. Every write goes to the journal first (durable when
// it returns, as the journal's contract says) and then to the model, so the wizard reads its own
// state from memory and never back from the store. The one exception is a record's samples
// (hours of them, too many to hold): VisitRecordChunks reads them back from the journal.
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
  void RecordStepDone(const std::string& step_id, const std::string& outcome) override;
  void RecordResult(const std::string& calibration_json) override;
  void MarkDone() override;
  void AppendRecordChunk(const std::string& step_id, const RecordChunk& chunk) override;

  // Copies, for the SessionJournal interface; the wizard reads the references below.
  std::vector<JournalCapture> Captures() const override { return captures_; }
  std::map<std::string, std::map<std::string, std::string>> Inputs() const override { return inputs_; }
  std::map<std::string, std::string> DoneSteps() const override { return done_; }
  std::optional<std::string> Result() const override { return result_; }
  RecordSummary RecordSummaryOf(const std::string& step_id) const override;
  void VisitRecordChunks(const std::string& step_id,
                         const std::function<void(const RecordChunk&)>& visit) const override;
  std::vector<std::string> RecordSteps() const override { return record_steps_; }

  const std::vector<JournalCapture>& captures() const { return captures_; }
  const std::map<std::string, std::map<std::string, std::string>>& inputs() const { return inputs_; }
  const std::map<std::string, std::string>& done_steps() const { return done_; }
  // The accepted capture of `step_id`; nullptr when it has none.
  const JournalCapture* CaptureOf(const std::string& step_id) const;
  // True when the step has a capture or is done.
  bool StepRecorded(const std::string& step_id) const;

 private:
  SessionJournal& journal_;  // borrowed: outlives the model
  std::vector<JournalCapture> captures_;
  std::map<std::string, std::map<std::string, std::string>> inputs_;
  std::map<std::string, std::string> done_;
  std::optional<std::string> result_;
  std::map<std::string, RecordSummary> records_;
  std::vector<std::string> record_steps_;
};

}  // namespace accelcal
