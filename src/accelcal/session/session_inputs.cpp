#include "accelcal/session/session_inputs.h"

namespace accelcal {

const std::optional<std::string>* WelcomeAnswers::Find(const std::string& key) const {
  if (key == welcome_key::kDevice) return &device;
  if (key == welcome_key::kOperator) return &operator_name;
  if (key == welcome_key::kPlace) return &place;
  if (key == welcome_key::kGravity) return &gravity;
  if (key == welcome_key::kEquipment) return &equipment;
  return nullptr;
}

WelcomeAnswers ReadWelcomeAnswers(const SessionInputs& inputs) {
  WelcomeAnswers answers;
  const auto welcome = inputs.find(kWelcomeStepId);
  if (welcome == inputs.end()) return answers;
  const auto read = [&](const char* key, std::optional<std::string>& into) {
    if (const auto value = welcome->second.find(key); value != welcome->second.end()) into = value->second;
  };
  read(welcome_key::kDevice, answers.device);
  read(welcome_key::kOperator, answers.operator_name);
  read(welcome_key::kPlace, answers.place);
  read(welcome_key::kGravity, answers.gravity);
  read(welcome_key::kEquipment, answers.equipment);
  return answers;
}

}  // namespace accelcal
