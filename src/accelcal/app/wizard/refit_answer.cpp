#include "accelcal/app/wizard/refit_answer.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include <fmt/core.h>

#include "accelcal/app/wizard/gravity_input.h"
#include "accelcal/session/equipment.h"

namespace accelcal {
namespace {

std::string Trimmed(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// The first word of `segment` and what follows it (trimmed).
std::pair<std::string, std::string> FirstWord(const std::string& segment) {
  std::istringstream in(segment);
  std::string word;
  in >> word;
  std::string rest;
  std::getline(in, rest);
  return {word, Trimmed(rest)};
}

// An item of the equipment table by its name ("ruler", "turntable", ...: session/equipment.h).
bool IsEquipmentRole(const std::string& word) {
  const std::vector<EquipmentRoleInfo>& roles = EquipmentRoles();
  return std::any_of(roles.begin(), roles.end(), [&](const EquipmentRoleInfo& r) { return r.key == word; });
}

}  // namespace

RefitAnswer ParseRefitAnswer(const std::string& text) {
  RefitAnswer out;
  std::vector<std::string> segments;
  std::istringstream in(text);
  for (std::string s; std::getline(in, s, ';');)
    if (!Trimmed(s).empty()) segments.push_back(Trimmed(s));
  if (segments.empty()) out.error = "nothing to correct: type what changed, or Enter to leave the session as it is";
  bool in_equipment = false;
  for (const std::string& segment : segments) {
    const auto [word, rest] = FirstWord(segment);
    if (in_equipment && IsEquipmentRole(word)) {
      *out.request.equipment_answer += "; " + segment;
      continue;
    }
    in_equipment = false;
    if (word == "gravity") {
      const GravityAnswer g = ParseGravityAnswer(rest);
      if (!g.ok()) return {{}, "gravity: " + g.error};
      out.request.gravity = g.gravity;
    } else if (word == "equipment") {
      if (rest.empty()) return {{}, "equipment: say what changed (ruler id RUL-07 u 0.05 cal C-2291)"};
      out.request.equipment_answer = rest;
      in_equipment = true;
    } else if (word == "device") {
      out.request.device = rest;
    } else if (word == "operator") {
      out.request.operator_name = rest;
    } else if (word == "place") {
      out.request.place = rest;
    } else {
      return {{}, fmt::format("'{}': start each correction with what it corrects: gravity, equipment, "
                              "device, operator or place (gravity lat -34.9 alt 43; equipment ruler cal C-2291)",
                              segment)};
    }
  }
  return out;
}

}  // namespace accelcal
