// What a bench sends the lab's store when it publishes a finished session (lab_store.h): the
// session, each sensor it calibrated (one today; a fixture of many boards later) with its
// calibration and verdict, and the equipment used. The certificates are rendered by the caller
// once the store has drawn their numbers (LabCertificateRenderer), inside the publishing
// transaction, so the bytes stored are the certificate as issued, number included.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace accelcal {

// One sensor of the session and its calibration.
struct LabSensorCalibration {
  int sensor_index = 0;          // 0, 1, ... within the session
  std::string device_serial;     // required: the register is by serial
  std::string calibration_json;  // the calibration file's text, as the session recorded it
  std::string verdict;           // as the certificate states it ("PASS", "FAIL", ...)
  std::string date_utc;          // when the calibration was made, ISO 8601
};

// An item of equipment the session used, as its certificate lists it.
struct LabEquipmentUse {
  std::string role;          // "ruler", "turntable", "level", "prism"
  std::string equipment_id;  // may be empty: not identified
  std::string name;
  std::string uncertainty;  // "0.5 mm", "not stated"
  std::string traceability;
};

struct LabPublication {
  std::string session_uuid;  // the natural key: a session published twice is one row
  std::string session_name;
  std::string procedure;
  std::string source;
  std::string operator_name;
  std::string place;
  std::string gravity;  // as answered: "standard", "9.7803 +- 1e-05", "lat -34.9 alt 43"
  double gravity_mps2 = 0.0;
  double gravity_sigma_mps2 = 0.0;
  std::string created_utc;
  std::string finished_utc;
  std::string accelcal_version;
  std::vector<LabSensorCalibration> sensors;  // at least one
  std::vector<LabEquipmentUse> equipment;
};

// A certificate's document as rendered.
struct LabDocument {
  std::string media_type;  // "text/html", "text/plain"
  std::string bytes;
};

// Renders the certificate of `sensor` with the lab's `certificate_number`.
using LabCertificateRenderer = std::function<std::vector<LabDocument>(const LabSensorCalibration& sensor,
                                                                      const std::string& certificate_number)>;

struct LabIssuedCertificate {
  int sensor_index = 0;
  std::string certificate_number;
  std::vector<LabDocument> documents;  // as stored in the lab
};

struct LabPublishResult {
  // False: the store already held this session (an earlier run, or a retry after a lost
  // connection whose commit had gone through): nothing was written, and `certificates` are the
  // ones it holds.
  bool newly_published = false;
  std::vector<LabIssuedCertificate> certificates;  // by sensor index
  std::string published_utc;                       // when the store took it
};

}  // namespace accelcal
