// What a wizard session records as it goes, so that nothing accepted is ever lost and an
// interrupted session resumes where it stopped. The SQLite store (session_store.h) is the real
// implementation; MakeMemoryJournal() is for tests.
//
// Contract: every Record* call is durable when it returns (committed in its own transaction),
// so a kill -9 right after loses nothing it recorded. Step ids are the procedure's.
#pragma once

#include <map>
#include <optional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accelcal/capture.h"

namespace accelcal {

struct JournalCapture {
  std::string step_id;
  Capture capture;  // with its raw samples
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
  // A step finished without a capture (leveling done, skipped, ...), with its outcome.
  virtual void RecordStepDone(const std::string& step_id, const std::string& outcome) = 0;
  // The session's result (the calibration file's JSON). A later one replaces it.
  virtual void RecordResult(const nlohmann::json& calibration) = 0;
  // The session is finished (its procedure completed); durable when it returns.
  virtual void MarkDone() = 0;

  // What was recorded (for resuming and for reports), in the order recorded.
  virtual std::vector<JournalCapture> Captures() const = 0;
  virtual std::map<std::string, std::map<std::string, std::string>> Inputs() const = 0;
  virtual std::map<std::string, std::string> DoneSteps() const = 0;  // step id -> outcome
  virtual std::optional<nlohmann::json> Result() const = 0;
};

std::unique_ptr<SessionJournal> MakeMemoryJournal();

}  // namespace accelcal
