#include "accelcal/session/equipment.h"

#include <cctype>
#include <cmath>

#include <fmt/core.h>

namespace accelcal {

const std::vector<EquipmentRoleInfo>& EquipmentRoles() {
  static const std::vector<EquipmentRoleInfo> roles = {
      {EquipmentRole::kRuler, "ruler", "turntable radius", "u_radius_mm", "mm", 1e-3},
      {EquipmentRole::kTurntable, "turntable", "turntable speed", "u_speed_percent", "%", 1e-2},
      {EquipmentRole::kLevel, "level", "table tilt after leveling", "u_tilt_deg", "deg",
       3.14159265358979323846 / 180.0},
      {EquipmentRole::kPrism, "prism", "prism squareness", "u_squareness_deg", "deg",
       3.14159265358979323846 / 180.0},
  };
  return roles;
}

const EquipmentRoleInfo& InfoOf(EquipmentRole role) {
  for (const EquipmentRoleInfo& info : EquipmentRoles())
    if (info.role == role) return info;
  return EquipmentRoles().front();  // unreachable: every role is listed
}

const EquipmentItem* FindEquipment(const std::vector<EquipmentItem>& items, EquipmentRole role) {
  for (const EquipmentItem& item : items)
    if (item.role == role) return &item;
  return nullptr;
}

ReferenceUncertainties ToReferenceUncertainties(const std::vector<EquipmentItem>& items,
                                                double gravity_sigma_mps2) {
  const auto u = [&](EquipmentRole role) {
    const EquipmentItem* item = FindEquipment(items, role);
    return item != nullptr ? item->standard_uncertainty : kNaN;
  };
  ReferenceUncertainties r;
  r.gravity_mps2 = gravity_sigma_mps2;
  r.radius_m = u(EquipmentRole::kRuler);
  r.rpm_relative = u(EquipmentRole::kTurntable);
  r.table_tilt_rad = u(EquipmentRole::kLevel);
  r.prism_squareness_rad = u(EquipmentRole::kPrism);
  return r;
}

bool IsPlaceholderId(const std::string& identification) {
  std::string lower;
  for (char c : identification)
    if (!std::isspace(static_cast<unsigned char>(c))) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower.empty() || lower.find("example") != std::string::npos) return true;
  for (const char* placeholder : {"tbd", "?", "-", "none", "n/a", "na", "xxx"})
    if (lower == placeholder) return true;
  return false;
}

bool IsVerified(const EquipmentItem& item) {
  return !IsPlaceholderId(item.identification) && !item.calibration.empty();
}

std::vector<std::string> UnidentifiedEquipment(const std::vector<EquipmentItem>& items) {
  std::vector<std::string> out;
  for (const EquipmentItem& item : items)
    if (IsPlaceholderId(item.identification))
      out.push_back(fmt::format("{} {}", InfoOf(item.role).key,
                                item.identification.empty() ? "(no id)" : item.identification));
  return out;
}

std::string DescribeUncertainty(const EquipmentItem& item) {
  if (!std::isfinite(item.standard_uncertainty)) return "not stated";
  const EquipmentRoleInfo& info = InfoOf(item.role);
  return fmt::format("{:g} {}", item.standard_uncertainty / info.to_si, info.file_unit);
}

}  // namespace accelcal
