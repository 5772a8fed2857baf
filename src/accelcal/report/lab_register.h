// What the lab's register says (the PostgreSQL store, lab/lab_store.h, docs/lab.md), in the
// shapes the command line shows and io/lab_register_json.h writes: a device's calibrations
// across every bench, what is due for recalibration, the lab's equipment and its certificates.
// Plain values: times are UTC ISO 8601 text ("2026-03-01T14:05:09.000Z"), dates "2026-03-01".
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace accelcal {

// One certificate of a device: a calibration published from a session.
struct LabHistoryEntry {
  std::string certificate_number;  // "LAB-000042"
  std::string session;             // the session's name on its bench
  std::string session_uuid;
  std::string bench;     // the role that published it
  std::string date_utc;  // when the calibration was made
  std::string verdict;   // as the certificate states it: "PASS", "FAIL", ...
  std::string status;    // "issued", "approved" or "withdrawn"
  std::string procedure;
  std::string operator_name;
  std::string approved_by, approved_utc;                      // empty unless approved
  std::string withdrawn_by, withdrawn_utc, withdrawn_reason;  // empty unless withdrawn
};

struct LabHistory {
  std::string serial;
  std::string device_type;               // empty: none assigned (the lab's default interval)
  std::vector<LabHistoryEntry> entries;  // by date, then certificate number
};

// A device or an item of equipment due for recalibration within the window asked.
struct LabDueItem {
  enum class Kind { kDevice, kEquipment };
  Kind kind = Kind::kDevice;
  std::string id;                 // device serial or equipment id
  std::string type;               // device type or equipment kind; may be empty
  std::string name;               // equipment name; empty for a device
  std::string last;               // device: last valid certificate number; equipment: its certificate
  std::string last_date;          // date of that calibration, "2026-03-01"; empty when none
  std::string due_date;           // "2027-03-01"; empty: no valid calibration at all (due now)
  std::optional<long> days_left;  // negative: overdue by that many days; empty with due_date
};

struct LabDueList {
  int within_days = 30;
  std::string today;              // the store's date, UTC
  std::vector<LabDueItem> items;  // most overdue first; devices and equipment mixed
};

// An item of the lab's equipment and its latest certificate.
struct LabEquipmentStatus {
  std::string id;
  std::string kind;  // "ruler", "turntable", "level", "prism", or the lab's word
  std::string name;
  std::string certificate_ref;    // empty: no certificate registered
  std::string calibrated_on;      // "2026-01-10"
  std::string valid_until;        // "2027-01-10"
  std::optional<long> days_left;  // until valid_until; negative: expired that long ago
  bool registered = true;         // false: an id asked about that the lab does not know

  bool valid() const { return registered && days_left && *days_left >= 0; }
};

}  // namespace accelcal
