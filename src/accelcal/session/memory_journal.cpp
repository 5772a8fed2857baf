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
    RecordSensorCaptures(step_id, {SensorCapture{0, capture}});
  }
  void RecordSensors(const Fixture& sensors) override {
    if (std::string why = sensors.Validate(); !why.empty()) throw Error("its sensors: " + why);
    if (sensors_) {
      if (sensors_->sensors.size() == sensors.sensors.size()) {
        bool same = true;
        for (std::size_t i = 0; i < sensors.sensors.size(); ++i)
          same = same && sensors_->sensors[i].serial == sensors.sensors[i].serial;
        if (same) return;
      }
      throw Error("the session already holds other sensors");
    }
    sensors_ = sensors;
  }
  std::optional<Fixture> Sensors() const override { return sensors_; }
  void RecordSensorCaptures(const std::string& step_id,
                            const std::vector<SensorCapture>& captures) override {
    const std::size_t count = sensors_ ? sensors_->sensors.size() : 1;
    for (const SensorCapture& n : captures) {
      if (n.sensor < 0 || static_cast<std::size_t>(n.sensor) >= count)
        throw Error(fmt::format("no sensor {}", n.sensor + 1));
      for (const JournalCapture& c : captures_)
        if (c.step_id == step_id && c.sensor == n.sensor)
          throw Error(fmt::format("step '{}' already has an accepted capture", step_id));
    }
    for (const SensorCapture& n : captures) {
      JournalCapture c{step_id, n.capture, ""};
      c.sensor = n.sensor;
      captures_.push_back(std::move(c));
    }
  }
  void RecordSensorRedoCaptures(const std::string& step_id, const std::vector<SensorCapture>& captures,
                                const std::string& superseded_step_id) override {
    std::vector<size_t> old;
    for (size_t i = 0; i < captures_.size(); ++i)
      if (captures_[i].step_id == superseded_step_id) old.push_back(i);
    if (old.empty())
      throw Error(fmt::format("step '{}' has no capture to supersede", superseded_step_id));
    for (size_t i : old)
      if (captures_[i].superseded())
        throw Error(fmt::format("the capture of step '{}' is already superseded", superseded_step_id));
    RecordSensorCaptures(step_id, captures);  // throws before anything changed
    for (size_t i : old) captures_[i].superseded_by = step_id;
  }
  std::vector<JournalCapture> SensorCaptures(int sensor) const override {
    std::vector<JournalCapture> out;
    for (const JournalCapture& c : captures_)
      if (c.sensor == sensor) out.push_back(c);
    return out;
  }
  void RecordRedoCapture(const std::string& step_id, const Capture& capture,
                         const std::string& superseded_step_id) override {
    auto old = std::find_if(captures_.begin(), captures_.end(), [&](const JournalCapture& c) {
      return c.step_id == superseded_step_id && c.sensor == 0;
    });
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
  void RecordResult(const std::string& calibration_json) override { RecordSensorResult(0, calibration_json); }
  void RecordSensorResult(int sensor, const std::string& calibration_json) override {
    results_[sensor] = calibration_json;
    ++result_counts_[sensor];
  }
  std::optional<std::string> SensorResult(int sensor) const override {
    if (auto r = results_.find(sensor); r != results_.end()) return r->second;
    return std::nullopt;
  }
  int SensorResultCount(int sensor) const override {
    auto n = result_counts_.find(sensor);
    return n == result_counts_.end() ? 0 : n->second;
  }
  void AppendRecordChunk(const std::string& step_id, const RecordChunk& chunk) override {
    CheckRecordChunk(step_id, chunk, RecordSummaryOf(step_id));
    if (records_.count(step_id) == 0) record_order_.push_back(step_id);
    records_[step_id].push_back(chunk);
  }
  void MarkDone() override { done_session_ = true; }
  std::vector<JournalCapture> Captures() const override { return SensorCaptures(0); }
  SessionInputs Inputs() const override { return inputs_; }
  std::map<std::string, std::string> DoneSteps() const override { return done_; }
  std::optional<std::string> Result() const override { return SensorResult(0); }
  int ResultCount() const override { return SensorResultCount(0); }
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
  std::vector<JournalCapture> captures_;  // every sensor's
  std::optional<Fixture> sensors_;
  std::map<std::string, std::map<std::string, std::string>> inputs_;
  std::map<std::string, std::string> done_;
  std::map<int, std::string> results_;  // each sensor's latest
  std::map<int, int> result_counts_;     // how many each sensor has had
  std::map<std::string, std::vector<RecordChunk>> records_;
  std::vector<std::string> record_order_;
  bool done_session_ = false;
};

}  // namespace

std::unique_ptr<SessionJournal> MakeMemoryJournal() { return std::make_unique<MemoryJournal>(); }

}  // namespace accelcal
