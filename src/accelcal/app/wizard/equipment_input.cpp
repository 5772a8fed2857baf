#include "accelcal/app/wizard/equipment_input.h"

#include <cmath>
#include <sstream>

#include <fmt/core.h>

namespace accelcal {
namespace {

const EquipmentRoleInfo* RoleNamed(const std::string& word) {
  for (const EquipmentRoleInfo& info : EquipmentRoles())
    if (info.key == word) return &info;
  return nullptr;
}

// One "ROLE id X u N" segment applied to `items`; empty, or why not.
std::string ApplySegment(const std::string& segment, std::vector<EquipmentItem>* items) {
  std::istringstream words(segment);
  std::string role_word;
  if (!(words >> role_word)) return "";  // an empty segment ("a; ; b") is harmless
  const EquipmentRoleInfo* info = RoleNamed(role_word);
  if (info == nullptr)
    return fmt::format("'{}' is not a piece of equipment: ruler, turntable, level or prism", role_word);
  EquipmentItem* item = nullptr;
  for (EquipmentItem& e : *items)
    if (e.role == info->role) item = &e;
  if (item == nullptr) {
    items->push_back({info->role, std::string(info->key), "", kNaN, "", ""});
    item = &items->back();
  }
  std::string key;
  bool changed = false;
  while (words >> key) {
    std::string value;
    if (!(words >> value)) return fmt::format("{}: '{}' needs a value after it", role_word, key);
    if (key == "id") {
      item->identification = value;
    } else if (key == "cal") {
      item->calibration = value;
    } else if (key == "u") {
      char* end = nullptr;
      const double v = std::strtod(value.c_str(), &end);
      if (end == value.c_str() || *end != '\0' || !std::isfinite(v) || v < 0.0)
        return fmt::format("{}: u must be a number >= 0 in {} (got '{}')", role_word, info->file_unit, value);
      item->standard_uncertainty = v * info->to_si;
    } else {
      return fmt::format("{}: '{}' is not something to change: id, u or cal", role_word, key);
    }
    changed = true;
  }
  if (!changed)
    return fmt::format("{}: say what changes (id TEXT, u NUMBER in {}, cal CERTIFICATE)", role_word, info->file_unit);
  return "";
}

}  // namespace

EquipmentAnswer ApplyEquipmentAnswer(const std::string& answer, std::vector<EquipmentItem> items) {
  EquipmentAnswer out;
  if (answer == "keep") {
    out.items = std::move(items);
    return out;
  }
  std::string segment;
  std::istringstream parts(answer);
  while (std::getline(parts, segment, ';')) {
    if (std::string why = ApplySegment(segment, &items); !why.empty()) {
      out.error = why;
      return out;
    }
  }
  out.items = std::move(items);
  return out;
}

std::string DescribeEquipment(const std::vector<EquipmentItem>& items) {
  std::string out;
  for (const EquipmentItem& e : items) {
    if (!out.empty()) out += "; ";
    out += fmt::format("{} {} {}", InfoOf(e.role).key, e.identification.empty() ? "(no id)" : e.identification,
                       DescribeUncertainty(e));
    if (!e.calibration.empty()) out += " (cal " + e.calibration + ")";
  }
  return out.empty() ? "none listed" : out;
}

}  // namespace accelcal

namespace accelcal {

EquipmentQuestionText EquipmentQuestion(const std::vector<EquipmentItem>& procedure_items,
                                        const std::string& offered) {
  const std::string answer = offered.empty() ? "keep" : offered;
  const EquipmentAnswer shown = ApplyEquipmentAnswer(answer, procedure_items);
  return {"Equipment: " + DescribeEquipment(shown.ok() ? shown.items : procedure_items) +
              ". Enter keeps it; or change items: ruler id RUL-07 u 0.4 cal C-2291; turntable u "
              "0.3 (u in mm, %, deg; cal: its calibration certificate)",
          answer};
}

std::string EquipmentAnswerOver(const std::string& default_answer, const std::string& typed) {
  if (typed.empty() || typed == "keep" || typed == default_answer || default_answer == "keep")
    return typed.empty() || typed == "keep" ? default_answer : typed;
  return default_answer + "; " + typed;
}

}  // namespace accelcal
