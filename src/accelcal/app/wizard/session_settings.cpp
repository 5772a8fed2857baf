#include "accelcal/app/wizard/session_settings.h"

#include <sstream>

#include <fmt/core.h>

#include "accelcal/app/wizard/equipment_input.h"
#include "accelcal/app/wizard/gravity_input.h"
#include "accelcal/app/wizard/session_gaps.h"

namespace accelcal {
namespace {

std::string InputOf(const SessionModel& model, const std::string& step, const std::string& key) {
  const auto inputs = model.inputs().find(step);
  if (inputs == model.inputs().end()) return "";
  const auto value = inputs->second.find(key);
  return value == inputs->second.end() ? "" : value->second;
}

}  // namespace

std::string TriadText(const Eigen::Vector3d& v) {
  return fmt::format("{:.6g} {:.6g} {:.6g}", v.x(), v.y(), v.z());
}

bool ParseTriad(const std::string& text, Eigen::Vector3d* v) {
  std::istringstream in(text);
  return static_cast<bool>(in >> (*v)[0] >> (*v)[1] >> (*v)[2]) && v->allFinite();
}

SessionSettings ReadSessionSettings(const Procedure& procedure, const SessionModel& model) {
  SessionSettings s;
  if (const std::string g = InputOf(model, kWelcomeStepId, "gravity"); !g.empty()) {
    const GravityAnswer answer = ParseGravityAnswer(g);
    if (answer.ok()) s.gravity = answer.gravity;
  }
  s.equipment_answer = InputOf(model, kWelcomeStepId, "equipment");
  const EquipmentAnswer edited = ApplyEquipmentAnswer(s.equipment_answer, procedure.equipment);
  s.equipment = edited.ok() ? edited.items : procedure.equipment;
  Eigen::Vector3d std_counts;
  if (ParseTriad(InputOf(model, kNoiseFloorStepId, "lowered_std_counts"), &std_counts))
    s.lowered_floor = NoiseFloor{std_counts, "lowered in an earlier run"};
  // A diagnosis decided in an earlier run: its outcome starts "adopted", "none" or "declined".
  for (const ProcedureStep& step : procedure.steps)
    if (step.kind == StepKind::kDiagnosis)
      if (auto d = model.done_steps().find(step.id); d != model.done_steps().end())
        s.adopt_effects = d->second.rfind("adopted", 0) == 0;
  return s;
}

}  // namespace accelcal
