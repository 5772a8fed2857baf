// The bench's equipment as a procedure lists it ([equipment] in the procedure file,
// docs/guide.md, "Procedures"), each item with its identification, the standard uncertainty it gives its
// reference quantity, and what that is traced to: the type B inputs of the uncertainty budget
// (calibration/uncertainty_budget.h) and the certificate's equipment list.
//
// Units: SI inside (m, rad, and the turntable speed relative: 0.002 = 0.2 %); the file states
// mm, deg and percent (EquipmentRoleInfo says which key and scale).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "accelcal/calibration/uncertainty_budget.h"

namespace accelcal {

enum class EquipmentRole {
  kRuler,      // ruler and compass: the turntable radius
  kTurntable,  // the turntable: its speed
  kLevel,      // the level: the table's residual tilt after leveling
  kPrism,      // the prism: the squareness of its faces
};

struct EquipmentRoleInfo {
  EquipmentRole role;
  std::string_view key;              // the table's name: "ruler", "turntable", "level", "prism"
  std::string_view quantity;         // what it gives: "turntable radius", ...
  std::string_view uncertainty_key;  // "u_radius_mm", "u_speed_percent", "u_tilt_deg", "u_squareness_deg"
  std::string_view file_unit;        // "mm", "%", "deg"
  double to_si;                      // SI value = file value * to_si
};

// The four roles, in the order the certificate lists them.
const std::vector<EquipmentRoleInfo>& EquipmentRoles();
const EquipmentRoleInfo& InfoOf(EquipmentRole role);

struct EquipmentItem {
  EquipmentRole role = EquipmentRole::kRuler;
  std::string name;            // "steel ruler 300 mm and compass"
  std::string identification;  // serial or inventory number; empty: not identified
  // Standard uncertainty (1-sigma) of its quantity, SI (see the header); NaN: not stated.
  double standard_uncertainty = kNaN;
  std::string traceability;    // what it is traced to, as the procedure states it
  // The item's own calibration or verification (certificate number, date): what makes its
  // stated uncertainty a verified one. Empty: not stated.
  std::string calibration;
};

// An identification that identifies nothing: empty, or a placeholder (one holding "example",
// as the shipped procedures' ids do, or "TBD", "?", "-", "none", "n/a").
bool IsPlaceholderId(const std::string& identification);
// Identified (IsPlaceholderId false) and with its calibration stated.
bool IsVerified(const EquipmentItem& item);
// The items not identified, as "ruler RUL-01 (example)", "level (no id)"; empty when all are.
std::vector<std::string> UnidentifiedEquipment(const std::vector<EquipmentItem>& items);

// The item of `role` in `items`; nullptr when absent.
const EquipmentItem* FindEquipment(const std::vector<EquipmentItem>& items, EquipmentRole role);

// The budget's type B inputs: each item's uncertainty, gravity's from the gravity question.
ReferenceUncertainties ToReferenceUncertainties(const std::vector<EquipmentItem>& items,
                                                double gravity_sigma_mps2);

// "0.5 mm", "0.2 %", "0.05 deg": the item's uncertainty in the file's unit; "not stated".
std::string DescribeUncertainty(const EquipmentItem& item);

}  // namespace accelcal
