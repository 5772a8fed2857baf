// What a session recorded that its calibration depends on, read back one way by the wizard
// (resuming) and by `accelcal refit` (app/refit_session.h): the welcome's gravity and
// equipment, a noise floor lowered by the captures, and the diagnosis's decision.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "accelcal/acquire/capture_engine/noise_floor.h"
#include "accelcal/app/wizard/session_model.h"
#include "accelcal/base/gravity.h"
#include "accelcal/session/equipment.h"
#include "accelcal/session/procedure.h"

namespace accelcal {

// The journal step of the noise floor's inputs ("std_counts"; "lowered_std_counts" and
// "lowered" when a capture proved it too high).
inline constexpr const char* kNoiseFloorStepId = "noise_floor";

struct SessionSettings {
  std::optional<GravitySpec> gravity;  // the welcome's answer; nullopt: none recorded
  std::string equipment_answer;        // the welcome's equipment answer as recorded; empty: none
  std::vector<EquipmentItem> equipment;  // the procedure's with that answer applied
  std::optional<NoiseFloor> lowered_floor;  // a floor lowered in an earlier run
  // The diagnosis's decision: false when the technician kept the base model (declined).
  bool adopt_effects = true;
};

SessionSettings ReadSessionSettings(const Procedure& procedure, const SessionModel& model);

// "x y z" of a noise floor as recorded, and back (false when it does not read).
std::string TriadText(const Eigen::Vector3d& v);
bool ParseTriad(const std::string& text, Eigen::Vector3d* v);

}  // namespace accelcal
