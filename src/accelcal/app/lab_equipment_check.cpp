#include "accelcal/app/lab_equipment_check.h"

#include <memory>

#include <fmt/core.h>

namespace accelcal {
namespace {

std::string Label(const LabEquipmentStatus& s) {
  return s.kind.empty() ? s.id : fmt::format("{} {}", s.kind, s.id);
}

// The warning for `s`; empty when it is valid beyond `soon_days`.
std::string WarningOf(const LabEquipmentStatus& s, int soon_days) {
  if (!s.registered)
    return fmt::format("{}: not in the lab's equipment register (its calibration cannot be checked)", s.id);
  if (!s.days_left) return fmt::format("{}: the lab holds no calibration certificate for it", Label(s));
  if (*s.days_left < 0)
    return fmt::format(
        "{}: its calibration expired on {} (certificate {}): have it recalibrated before it is "
        "used for a certificate",
        Label(s), s.valid_until, s.certificate_ref);
  if (*s.days_left <= soon_days)
    return fmt::format("{}: its calibration runs out on {} (in {} day(s); certificate {})", Label(s),
                       s.valid_until, *s.days_left, s.certificate_ref);
  return "";
}

}  // namespace

EquipmentCheck CheckEquipment(const LabStore& lab, const std::vector<std::string>& ids, int soon_days) {
  std::vector<std::string> asked;
  for (const std::string& id : ids)
    if (!id.empty()) asked.push_back(id);
  EquipmentCheck check;
  check.items = lab.EquipmentStatus(asked);
  for (const LabEquipmentStatus& s : check.items) {
    const std::string warning = WarningOf(s, soon_days);
    if (warning.empty()) continue;
    check.warnings.push_back(warning);
    if (!s.valid()) check.any_expired_or_unknown = true;
  }
  return check;
}

WelcomeLabCheck WelcomeEquipmentWarnings(const std::vector<EquipmentItem>& equipment) {
  WelcomeLabCheck out;
  if (!LabConfigured()) return out;
  std::vector<std::string> ids;
  for (const EquipmentItem& item : equipment) ids.push_back(item.identification);
  try {
    const std::unique_ptr<LabStore> lab = LabStore::ConnectQuickly();
    out.warnings = CheckEquipment(*lab, ids).warnings;
  } catch (const LabError& e) {
    if (e.unreachable()) out.unreachable = e.what();
    else out.warnings.push_back(fmt::format("the equipment's calibration dates could not be checked: {}", e.what()));
  }
  return out;
}

std::function<WelcomeLabCheck(const std::vector<EquipmentItem>&)> WelcomeEquipmentCheck() {
  auto unreachable = std::make_shared<std::string>();
  return [unreachable](const std::vector<EquipmentItem>& equipment) {
    if (!unreachable->empty()) return WelcomeLabCheck{{}, *unreachable};
    WelcomeLabCheck check = WelcomeEquipmentWarnings(equipment);
    *unreachable = check.unreachable;
    return check;
  };
}

}  // namespace accelcal
