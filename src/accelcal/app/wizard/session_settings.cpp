#include "accelcal/app/wizard/session_settings.h"

#include <sstream>

#include <fmt/core.h>

#include "accelcal/app/wizard/equipment_input.h"
#include "accelcal/app/wizard/gravity_input.h"

namespace accelcal {

std::string TriadText(const Eigen::Vector3d& v) {
  return fmt::format("{:.6g} {:.6g} {:.6g}", v.x(), v.y(), v.z());
}

bool ParseTriad(const std::string& text, Eigen::Vector3d* v) {
  std::istringstream in(text);
  return static_cast<bool>(in >> (*v)[0] >> (*v)[1] >> (*v)[2]) && v->allFinite();
}

std::optional<GravitySpec> RecordedGravity(const WelcomeAnswers& answers) {
  if (!answers.gravity || answers.gravity->empty()) return std::nullopt;
  const GravityAnswer answer = ParseGravityAnswer(*answers.gravity);
  if (!answer.ok()) return std::nullopt;
  return answer.gravity;
}

std::vector<EquipmentItem> RecordedEquipment(const WelcomeAnswers& answers, const Procedure& procedure) {
  const EquipmentAnswer edited = ApplyEquipmentAnswer(answers.equipment.value_or(""), procedure.equipment);
  return edited.ok() ? edited.items : procedure.equipment;
}

std::optional<NoiseFloor> RecordedLoweredFloor(const SessionInputs& inputs) {
  const auto floor = inputs.find(kNoiseFloorStepId);
  if (floor == inputs.end()) return std::nullopt;
  const auto lowered = floor->second.find(noise_floor_key::kLoweredStdCounts);
  Eigen::Vector3d std_counts;
  if (lowered == floor->second.end() || !ParseTriad(lowered->second, &std_counts)) return std::nullopt;
  return NoiseFloor{std_counts, "lowered in an earlier run"};
}

// RecordedAdoptEffects is the diagnosis's (steps/diagnosis_step.cpp: it reads what its step
// recorded).

SessionSettings ReadSessionSettings(const Procedure& procedure, const SessionModel& model) {
  const WelcomeAnswers answers = ReadWelcomeAnswers(model.inputs());
  SessionSettings s;
  s.gravity = RecordedGravity(answers);
  s.equipment_answer = answers.equipment.value_or("");
  s.equipment = RecordedEquipment(answers, procedure);
  s.lowered_floor = RecordedLoweredFloor(model.inputs());
  s.adopt_effects = RecordedAdoptEffects(procedure, model);
  return s;
}

}  // namespace accelcal
