#include "accelcal/report/completeness.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>
#include <fmt/format.h>

#include "accelcal/calibration/diagnosis/effect.h"

namespace accelcal {
namespace {

// The required steps skipped in one line (a skipped mounting's three runs are one fact), the
// others each with why.
void AddSessionGaps(const std::optional<SessionGaps>& gaps, std::vector<std::string>* out) {
  if (!gaps) return;
  std::vector<std::string> skipped;
  for (const SessionGaps::Step& s : gaps->steps)
    if (s.required && s.why == "skipped") skipped.push_back(fmt::format("'{}'", s.title));
  if (skipped.size() == 1) out->push_back(fmt::format("required step {} skipped", skipped.front()));
  if (skipped.size() > 1) out->push_back(fmt::format("required steps skipped: {}", fmt::join(skipped, ", ")));
  for (const SessionGaps::Step& s : gaps->steps)
    if (s.required && s.why != "skipped") out->push_back(fmt::format("required step '{}' {}", s.title, s.why));
  for (const std::string& what : gaps->identification)
    out->push_back(fmt::format("no {} recorded (the procedure requires it)", what));
}

void AddEquipment(const std::vector<EquipmentItem>& equipment, std::vector<std::string>* out) {
  const std::vector<std::string> unidentified = UnidentifiedEquipment(equipment);
  if (unidentified.empty()) return;
  out->push_back(fmt::format("equipment not identified: {}: give each item's own identification (the "
                             "procedure's [equipment], or at the welcome: ruler id RUL-07)",
                             fmt::join(unidentified, ", ")));
}

// The limits on U (and a guard band) judge U: it must hold every reference quantity.
void AddBudget(const ReportInputs& in, const std::vector<LimitCheck>& checks, std::vector<std::string>* out) {
  const bool judges_u = std::any_of(checks.begin(), checks.end(), [](const LimitCheck& c) { return c.on_uncertainty; }) ||
                        (in.limits && in.limits->AnyTolerance() && in.limits->decision_rule == DecisionRule::kGuardBand);
  if (!judges_u) return;
  const std::optional<UncertaintyBudget>& budget = in.calibration.budget;
  if (!budget || budget->parameters.empty()) {
    out->push_back("no uncertainty budget: U is twice the fit's 1-sigma, type A alone, and the limits on U "
                   "need the reference quantities' uncertainties too (a wizard session's calibration "
                   "carries its budget)");
    return;
  }
  if (!budget->not_stated.empty())
    out->push_back(fmt::format("U lacks the uncertainty of the {}: the procedure's [equipment] states none",
                               fmt::join(budget->not_stated, ", ")));
}

bool UsesTurntable(const Calibration& cal) {
  return std::any_of(cal.captures.begin(), cal.captures.end(),
                     [](const CalibrationCapture& c) { return c.used && c.kind == CaptureKind::kTurntable; });
}

// "the turntable's speed (TT-01 (example): no calibration stated)" for an item not verified.
std::string NotVerified(const std::vector<EquipmentItem>& equipment, EquipmentRole role, const char* what) {
  const EquipmentItem* item = FindEquipment(equipment, role);
  if (item == nullptr) return fmt::format("{} (no {} listed)", what, InfoOf(role).key);
  if (IsVerified(*item)) return "";
  const std::string id = item->identification.empty() ? std::string("no id") : item->identification;
  return fmt::format("{} ({}: {})", what, id,
                     IsPlaceholderId(item->identification) ? "not identified" : "no calibration stated");
}

// The item of the equipment table named `key` ("ruler", "turntable"); nullptr when none is.
const EquipmentRoleInfo* EquipmentRoleNamed(std::string_view key) {
  for (const EquipmentRoleInfo& r : EquipmentRoles())
    if (r.key == key) return &r;
  return nullptr;
}

// A scale found and corrected, against what the verified item allows (k = 2 on both the
// item's u and the effect's own 1-sigma); empty when within it. The item is the one the effect
// names (Effect::VerifiedBy), its unit the equipment table's.
std::string BeyondVerified(const CalibrationEffect& e, const std::vector<EquipmentItem>& equipment,
                           const GravitySpec& gravity) {
  if (e.parameters.empty()) return "";
  const Effect* effect = FindEffect(e.name);
  const std::optional<Effect::VerifyingEquipment> verified = effect ? effect->VerifiedBy() : std::nullopt;
  const EquipmentRoleInfo* role = verified ? EquipmentRoleNamed(verified->item) : nullptr;
  if (role == nullptr) return "";
  const EffectParameter& p = e.parameters.front();
  const EquipmentItem* item = FindEquipment(equipment, role->role);
  if (item == nullptr || !std::isfinite(item->standard_uncertainty)) return "";
  const double allowed = 2.0 * std::hypot(item->standard_uncertainty, std::isfinite(p.sigma) ? p.sigma : 0.0);
  if (std::fabs(p.value) <= allowed) return "";
  const double scale = 1.0 / role->to_si;
  return fmt::format(
      "the turntable's {0} is verified to u = {1:g} {2} ({3}, calibration {4}) but the data finds it "
      "{5:.2g} {2} off: either the {0} is not what its verification says (check it again: {6}) or the "
      "local gravity used, {7}, is wrong (a wrong gravity gives the same signature: check it)",
      verified->quantity, item->standard_uncertainty * scale, role->file_unit, item->identification,
      item->calibration, std::fabs(p.value) * scale, verified->checked_with, gravity.Describe());
}

void AddGravityOrTurntable(const ReportInputs& in, std::vector<std::string>* out) {
  const Calibration& cal = in.calibration;
  std::vector<const CalibrationEffect*> adopted;
  for (const CalibrationEffect& e : cal.effects)
    if (TakesGravityErrorForItsOwn(e.name)) adopted.push_back(&e);
  const bool found = !adopted.empty() || (in.gaps && !in.gaps->gravity_ambiguity.empty());
  if (!found || !UsesTurntable(cal)) return;
  if (cal.gravity.is_standard()) {
    out->push_back("gravity not established: the diagnosis found a turntable speed or radius scale "
                   "while gravity is the standard value (a gravity error looks the same)");
    return;
  }
  if (adopted.empty()) {
    out->push_back("a turntable speed or radius scale was found and not corrected (the base model was "
                   "kept): the scales carry it, and the data cannot tell a wrong turntable from a wrong "
                   "local gravity: check both");
    return;
  }
  std::vector<std::string> unverified;
  for (const auto& [role, what] : {std::pair{EquipmentRole::kTurntable, "the turntable's speed"},
                                   std::pair{EquipmentRole::kRuler, "the radius"}})
    if (std::string why = NotVerified(in.equipment, role, what); !why.empty()) unverified.push_back(why);
  std::vector<std::string> names;
  for (const CalibrationEffect* e : adopted) names.push_back(e->name);
  if (!unverified.empty()) {
    out->push_back(fmt::format(
        "{} found, and the data cannot tell it from a wrong local gravity ({}): PASS needs the turntable's "
        "speed and radius verified, and {} not: check the speed with a calibrated tachometer and the radius "
        "with a calibrated ruler, state their calibration in the procedure's [equipment] (calibration = "
        "...) or at the welcome (cal ...), and check the local gravity",
        fmt::join(names, " and "), cal.gravity.Describe(), fmt::join(unverified, " and ")));
    return;
  }
  for (const CalibrationEffect* e : adopted)
    if (std::string why = BeyondVerified(*e, in.equipment, cal.gravity); !why.empty()) out->push_back(why);
}

}  // namespace

std::vector<std::string> IncompleteReasons(const ReportInputs& in, const std::vector<LimitCheck>& checks) {
  std::vector<std::string> out = in.damaged_captures;
  AddSessionGaps(in.gaps, &out);
  AddEquipment(in.equipment, &out);
  AddBudget(in, checks, &out);
  AddGravityOrTurntable(in, &out);
  return out;
}

}  // namespace accelcal
