#include <algorithm>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/session/session_journal.h"

namespace accelcal {
namespace {

class MemoryJournal final : public SessionJournal {
 public:
  void RecordInput(const std::string& step_id, const std::string& key,
                   const std::string& value) override {
    inputs_[step_id][key] = value;
  }
  void RecordCapture(const std::string& step_id, const Capture& capture) override {
    for (const JournalCapture& c : captures_)
      if (c.step_id == step_id)
        throw Error(fmt::format("step '{}' already has an accepted capture", step_id));
    captures_.push_back({step_id, capture, ""});
  }
  void RecordRedoCapture(const std::string& step_id, const Capture& capture,
                         const std::string& superseded_step_id) override {
    auto old = std::find_if(captures_.begin(), captures_.end(),
                            [&](const JournalCapture& c) { return c.step_id == superseded_step_id; });
    if (old == captures_.end())
      throw Error(fmt::format("step '{}' has no capture to supersede", superseded_step_id));
    if (old->superseded())
      throw Error(fmt::format("the capture of step '{}' is already superseded", superseded_step_id));
    const size_t old_index = static_cast<size_t>(old - captures_.begin());
    RecordCapture(step_id, capture);  // throws before anything changed
    captures_[old_index].superseded_by = step_id;
  }
  void RecordStepDone(const std::string& step_id, const std::string& outcome) override {
    done_[step_id] = outcome;
  }
  void RecordResult(const std::string& calibration_json) override {
    result_ = calibration_json;
    ++results_;
  }
  void AppendRecordChunk(const std::string& step_id, const RecordChunk& chunk) override {
    CheckRecordChunk(step_id, chunk, RecordSummaryOf(step_id));
    if (records_.count(step_id) == 0) record_order_.push_back(step_id);
    records_[step_id].push_back(chunk);
  }
  void MarkDone() override { done_session_ = true; }
  std::vector<JournalCapture> Captures() const override { return captures_; }
  SessionInputs Inputs() const override { return inputs_; }
  std::map<std::string, std::string> DoneSteps() const override { return done_; }
  std::optional<std::string> Result() const override { return result_; }
  int ResultCount() const override { return results_; }
  RecordSummary RecordSummaryOf(const std::string& step_id) const override {
    RecordSummary s;
    if (auto r = records_.find(step_id); r != records_.end())
      for (const RecordChunk& c : r->second) s = AddToSummary(s, c);
    return s;
  }
  void VisitRecordChunks(const std::string& step_id,
                         const std::function<void(const RecordChunk&)>& visit) const override {
    if (auto r = records_.find(step_id); r != records_.end())
      for (const RecordChunk& c : r->second) visit(c);
  }
  std::vector<std::string> RecordSteps() const override { return record_order_; }

 private:
  std::vector<JournalCapture> captures_;
  std::map<std::string, std::map<std::string, std::string>> inputs_;
  std::map<std::string, std::string> done_;
  std::optional<std::string> result_;
  int results_ = 0;
  std::map<std::string, std::vector<RecordChunk>> records_;
  std::vector<std::string> record_order_;
  bool done_session_ = false;
};

}  // namespace

std::unique_ptr<SessionJournal> MakeMemoryJournal() { return std::make_unique<MemoryJournal>(); }

}  // namespace accelcal
