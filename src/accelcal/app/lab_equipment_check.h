// The bench's equipment against the lab's register (lab/lab_store.h): an item whose calibration
// has run out, runs out soon, or that the lab does not know. For `accelcal lab equipment --check`
// and the wizard's welcome, which warns before the first capture (a certificate made with
// expired equipment is not traceable).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "accelcal/app/wizard/wizard_options.h"

#include "accelcal/lab/lab_store.h"
#include "accelcal/session/equipment.h"

namespace accelcal {

inline constexpr int kEquipmentSoonDays = 30;

struct EquipmentCheck {
  std::vector<LabEquipmentStatus> items;  // in the order asked
  std::vector<std::string> warnings;      // one line each, plain words; empty: all valid
  bool any_expired_or_unknown = false;    // beyond a warning of "soon"
};

// The items `ids` (empty ids are skipped) as the lab holds them, with a warning for each one
// expired, unknown, or running out within `soon_days`.
EquipmentCheck CheckEquipment(const LabStore& lab, const std::vector<std::string>& ids,
                              int soon_days = kEquipmentSoonDays);

// The wizard's welcome: the identified items of `equipment` (the procedure's, as the welcome
// edited them) checked against the lab when this bench is pointed at one (LabConfigured());
// nothing when it is not. The lab is given kLabQuickConnectTimeoutS to answer; one that cannot
// be reached is the outcome's `unreachable`, never an error: the bench keeps working.
WelcomeLabCheck WelcomeEquipmentWarnings(const std::vector<EquipmentItem>& equipment);

// WizardOptions::check_equipment: WelcomeEquipmentWarnings, except that once the lab could not
// be reached it is not tried again in this session (the welcome's equipment answer would wait
// for it once more): the same `unreachable` comes back at once.
std::function<WelcomeLabCheck(const std::vector<EquipmentItem>&)> WelcomeEquipmentCheck();

}  // namespace accelcal
