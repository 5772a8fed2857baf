#include "accelcal/session/sensor_journal_view.h"

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal {

SensorJournalView::SensorJournalView(SessionJournal& session, int sensor)
    : session_(session), sensor_(sensor), fixture_(SessionSensors(session)) {
  if (sensor < 0 || static_cast<std::size_t>(sensor) >= fixture_.sensors.size()) {
    throw Error(fmt::format("--sensor {}: the session has {} sensor(s) (1 to {})", sensor + 1,
                            fixture_.sensors.size(), fixture_.sensors.size()));
  }
}

void SensorJournalView::ReadOnly(const char* what) const {
  throw Error(fmt::format("sensor {} of a session is read through it: {} goes to the session",
                          sensor_ + 1, what));
}

void SensorJournalView::RecordInput(const std::string&, const std::string&, const std::string&) {
  ReadOnly("an input");
}
void SensorJournalView::RecordCapture(const std::string& step_id, const Capture& capture) {
  session_.RecordSensorCaptures(step_id, {SensorCapture{sensor_, capture}});
}
void SensorJournalView::RecordRedoCapture(const std::string&, const Capture&, const std::string&) {
  ReadOnly("a redo");
}
void SensorJournalView::RecordStepDone(const std::string&, const std::string&) {
  ReadOnly("a step's outcome");
}
void SensorJournalView::RecordResult(const std::string& calibration_json) {
  session_.RecordSensorResult(sensor_, calibration_json);
}
void SensorJournalView::MarkDone() { ReadOnly("the session's end"); }
void SensorJournalView::AppendRecordChunk(const std::string&, const RecordChunk&) {
  ReadOnly("a record");
}

std::vector<JournalCapture> SensorJournalView::Captures() const {
  return session_.SensorCaptures(sensor_);
}

std::vector<DamagedCapture> SensorJournalView::DamagedCaptures() const {
  std::vector<DamagedCapture> mine;
  for (DamagedCapture& d : session_.DamagedCaptures())
    if (d.sensor == sensor_) mine.push_back(std::move(d));
  return mine;
}

SessionInputs SensorJournalView::Inputs() const {
  SessionInputs inputs = session_.Inputs();
  std::string at = kWelcomeStepId;
  for (auto& [step, values] : inputs)
    if (values.erase(welcome_key::kDevice) > 0) at = step;
  inputs[at][welcome_key::kDevice] = fixture_sensor().serial;
  return inputs;
}

RecordSummary SensorJournalView::RecordSummaryOf(const std::string& step_id) const {
  return sensor_ == 0 ? session_.RecordSummaryOf(step_id) : RecordSummary{};
}

void SensorJournalView::VisitRecordChunks(const std::string& step_id,
                                          const std::function<void(const RecordChunk&)>& visit) const {
  if (sensor_ == 0) session_.VisitRecordChunks(step_id, visit);
}

std::vector<std::string> SensorJournalView::RecordSteps() const {
  return sensor_ == 0 ? session_.RecordSteps() : std::vector<std::string>{};
}

}  // namespace accelcal
