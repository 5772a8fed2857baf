// What a session recorded that its calibration depends on, read back one way by the wizard's
// steps (resuming: the welcome, the noise floor, the diagnosis) and by `accelcal refit`
// (app/refit_session.h): the welcome's gravity and equipment, a noise floor lowered by the
// captures, and the diagnosis's decision. The journal's keys are session/session_inputs.h's.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/acquire/capture_engine/noise_floor.h"
#include "accelcal/app/wizard/session_model.h"
#include "accelcal/base/gravity.h"
#include "accelcal/session/equipment.h"
#include "accelcal/session/procedure.h"
#include "accelcal/session/session_inputs.h"

namespace accelcal {

struct SessionSettings {
  std::optional<GravitySpec> gravity;  // the welcome's answer; nullopt: none recorded
  std::string equipment_answer;        // the welcome's equipment answer as recorded; empty: none
  std::vector<EquipmentItem> equipment;  // the procedure's with that answer applied
  std::optional<NoiseFloor> lowered_floor;  // a floor lowered in an earlier run
  // The diagnosis's decision: false when the technician kept the base model (declined).
  bool adopt_effects = true;
};

SessionSettings ReadSessionSettings(const Procedure& procedure, const SessionModel& model);

// The parts, for the step that owns each:
// the welcome's gravity (nullopt: none recorded, or one that does not read);
std::optional<GravitySpec> RecordedGravity(const WelcomeAnswers& answers);
// the procedure's equipment with the welcome's answer applied (the procedure's when none);
std::vector<EquipmentItem> RecordedEquipment(const WelcomeAnswers& answers, const Procedure& procedure);
// a floor the captures lowered in an earlier run (they were judged again with it);
std::optional<NoiseFloor> RecordedLoweredFloor(const SessionInputs& inputs);
// the diagnosis decided in an earlier run: its outcome starts "adopted", "none" or "declined";
// true (adopt) when no diagnosis is recorded.
bool RecordedAdoptEffects(const Procedure& procedure, const SessionModel& model);

// "x y z" of a noise floor as recorded, and back (false when it does not read).
std::string TriadText(const Eigen::Vector3d& v);
bool ParseTriad(const std::string& text, Eigen::Vector3d* v);

}  // namespace accelcal
