// One sensor of a several-sensor session seen as a one-sensor session (issue 31): its captures,
// its result, its serial as the device; so every reader of a session (the report, the
// certificate, the exports, the device's history) reads each sensor as it reads any session,
// unchanged. `--sensor N` opens this view.
//
// What the view shows of sensor i:
//   Captures()        the session's SensorCaptures(i);  DamagedCaptures(): sensor i's damaged ones
//   Inputs()          the session's, with the device input (welcome_key::kDevice) replaced by
//                     the sensor's serial, at the step that held it (or "welcome")
//   Result()          SensorResult(i); RecordResult records sensor i's
//   records           a record step's: the lead's under the step's own id (the sensor that led
//                     the wizard: its serial at kSensorSetStep / kSensorSetLeadKey; sensor 0
//                     when none is recorded), each other sensor's under SensorRecordStep(step,
//                     its serial), seen through its view under the step's own id
// Every other write throws accelcal::Error (the session is written through itself).
#pragma once

#include <string>

#include "accelcal/session/session_journal.h"

namespace accelcal {

// The inputs of a several-sensor session's set (at the pseudo step kSensorSetStep): the serial
// of the sensor that led the wizard (kSensorSetLeadKey); app/fixture/sensor_batch.h adds why a
// sensor was left out of a pose.
inline constexpr const char* kSensorSetStep = "fixture";
inline constexpr const char* kSensorSetLeadKey = "lead";
// The plate's placement uncertainty as the fixture states it (Fixture::placement_u_rad), deg;
// kept with the sensors (the store writes and reads it with them), absent when not stated.
inline constexpr const char* kSensorSetPlacementKey = "placement_u_deg";

// Where a record step's samples of a sensor other than the lead are kept: "noise" of "B03" is
// the record "noise@B03" (the lead's is "noise", what the wizard reads back on a resume).
std::string SensorRecordStep(const std::string& step_id, const std::string& serial);
// A record of another sensor than the lead (its id has the '@').
bool IsSensorRecordStep(const std::string& record_step_id);

class SensorJournalView final : public SessionJournal {
 public:
  // Throws accelcal::Error when `sensor` is not one of the session's (SessionSensors).
  SensorJournalView(SessionJournal& session, int sensor);

  int sensor() const { return sensor_; }
  const FixtureSensor& fixture_sensor() const { return fixture_.sensors[static_cast<size_t>(sensor_)]; }

  void RecordInput(const std::string& step_id, const std::string& key,
                   const std::string& value) override;
  void RecordCapture(const std::string& step_id, const Capture& capture) override;
  void RecordRedoCapture(const std::string& step_id, const Capture& capture,
                         const std::string& superseded_step_id) override;
  void RecordStepDone(const std::string& step_id, const std::string& outcome) override;
  void RecordResult(const std::string& calibration_json) override;
  void MarkDone() override;
  void AppendRecordChunk(const std::string& step_id, const RecordChunk& chunk) override;

  std::vector<JournalCapture> Captures() const override;
  std::vector<DamagedCapture> DamagedCaptures() const override;
  SessionInputs Inputs() const override;
  std::map<std::string, std::string> DoneSteps() const override { return session_.DoneSteps(); }
  std::optional<std::string> Result() const override { return session_.SensorResult(sensor_); }
  int ResultCount() const override { return session_.SensorResultCount(sensor_); }
  RecordSummary RecordSummaryOf(const std::string& step_id) const override;
  void VisitRecordChunks(const std::string& step_id,
                         const std::function<void(const RecordChunk&)>& visit) const override;
  std::vector<std::string> RecordSteps() const override;

 private:
  [[noreturn]] void ReadOnly(const char* what) const;

  // This sensor's record of `step_id`.
  std::string MyRecordStep(const std::string& step_id) const;

  SessionJournal& session_;
  int sensor_;
  Fixture fixture_;
  int lead_ = 0;  // the sensor that led the wizard
};

}  // namespace accelcal
