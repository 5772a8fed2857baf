#include "accelcal/app/wizard/session_model.h"

#include <algorithm>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal {

SessionModel::SessionModel(SessionJournal& journal)
    : journal_(journal),
      captures_(journal.Captures()),
      inputs_(journal.Inputs()),
      done_(journal.DoneSteps()),
      result_(journal.Result()),
      record_steps_(journal.RecordSteps()) {
  for (const std::string& step : record_steps_) records_[step] = journal.RecordSummaryOf(step);
  // Each capture's statistics computed once here; every copy the wizard makes carries them.
  for (const JournalCapture& c : captures_) c.capture.stats();
}

void SessionModel::RecordInput(const std::string& step_id, const std::string& key,
                               const std::string& value) {
  journal_.RecordInput(step_id, key, value);
  inputs_[step_id][key] = value;
}

void SessionModel::RecordCapture(const std::string& step_id, const Capture& capture) {
  if (ExactCapture(step_id) != nullptr)
    throw Error(fmt::format("step '{}' already has an accepted capture", step_id));
  journal_.RecordCapture(step_id, capture);
  captures_.push_back({step_id, capture, ""});
}

void SessionModel::RecordRedoCapture(const std::string& step_id, const Capture& capture,
                                     const std::string& superseded_step_id) {
  if (ExactCapture(step_id) != nullptr)
    throw Error(fmt::format("step '{}' already has an accepted capture", step_id));
  journal_.RecordRedoCapture(step_id, capture, superseded_step_id);
  for (JournalCapture& c : captures_)
    if (c.step_id == superseded_step_id) c.superseded_by = step_id;
  captures_.push_back({step_id, capture, ""});
}

void SessionModel::RecordStepDone(const std::string& step_id, const std::string& outcome) {
  journal_.RecordStepDone(step_id, outcome);
  done_[step_id] = outcome;
}

void SessionModel::RecordResult(const std::string& calibration_json) {
  journal_.RecordResult(calibration_json);
  result_ = calibration_json;
}

void SessionModel::MarkDone() { journal_.MarkDone(); }

void SessionModel::AppendRecordChunk(const std::string& step_id, const RecordChunk& chunk) {
  journal_.AppendRecordChunk(step_id, chunk);
  if (records_.count(step_id) == 0) record_steps_.push_back(step_id);
  records_[step_id] = AddToSummary(records_[step_id], chunk);
}

RecordSummary SessionModel::RecordSummaryOf(const std::string& step_id) const {
  const auto r = records_.find(step_id);
  return r == records_.end() ? RecordSummary() : r->second;
}

void SessionModel::VisitRecordChunks(const std::string& step_id,
                                     const std::function<void(const RecordChunk&)>& visit) const {
  journal_.VisitRecordChunks(step_id, visit);
}

const JournalCapture* SessionModel::ExactCapture(const std::string& journal_step_id) const {
  const auto c = std::find_if(captures_.begin(), captures_.end(),
                              [&](const JournalCapture& j) { return j.step_id == journal_step_id; });
  return c == captures_.end() ? nullptr : &*c;
}

std::string SessionModel::ProcedureStepOf(const std::string& journal_step_id) {
  return journal_step_id.substr(0, journal_step_id.find('#'));
}

std::string SessionModel::LeftOutReason(const JournalCapture& c) const {
  const auto step = inputs_.find(ProcedureStepOf(c.step_id));
  if (step == inputs_.end()) return "";
  const auto mark = step->second.find(fmt::format("left_out {}", c.capture.id));
  return mark == step->second.end() ? "" : mark->second;
}

void SessionModel::MarkLeftOut(const JournalCapture& c, const std::string& reason) {
  RecordInput(ProcedureStepOf(c.step_id), fmt::format("left_out {}", c.capture.id), reason);
}

const JournalCapture* SessionModel::CaptureOf(const std::string& step_id) const {
  const JournalCapture* found = nullptr;
  for (const JournalCapture& c : captures_)
    if (ProcedureStepOf(c.step_id) == step_id && LeftOutReason(c).empty() && !c.superseded()) found = &c;
  return found;
}

std::string SessionModel::NextCaptureStepId(const std::string& step_id) const {
  if (ExactCapture(step_id) == nullptr) return step_id;
  for (int attempt = 2;; ++attempt) {
    const std::string id = fmt::format("{}#{}", step_id, attempt);
    if (ExactCapture(id) == nullptr) return id;
  }
}

bool SessionModel::StepRecorded(const std::string& step_id) const {
  return done_.count(step_id) != 0 || CaptureOf(step_id) != nullptr;
}

}  // namespace accelcal
