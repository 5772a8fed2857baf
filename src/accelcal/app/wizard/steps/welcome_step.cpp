#include "accelcal/app/wizard/steps/welcome_step.h"

#include <algorithm>

#include <fmt/core.h>

#include "accelcal/app/wizard/equipment_input.h"
#include "accelcal/app/wizard/gravity_input.h"
#include "accelcal/app/wizard/quantity_input.h"
#include "accelcal/session/session_inputs.h"

namespace accelcal {

WelcomeStep::Question WelcomeStep::QuestionAt(int index) const {
  const WizardOptions& o = session_.options;
  switch (index) {
    case 0: return {welcome_key::kDevice, "Device serial number", o.default_device};
    case 1: return {welcome_key::kOperator, "Operator", o.default_operator};
    case 2: return {welcome_key::kPlace, "Place (lab, bench)", o.default_place};
    case 4:
      return {welcome_key::kEquipment,
              "Equipment: " + DescribeEquipment(session_.procedure.equipment) +
                  ". Enter keeps it; or change items: ruler id RUL-07 u 0.4; turntable u 0.3 "
                  "(u in mm, %, deg)",
              "keep"};
    default:
      return {welcome_key::kGravity,
              "Local gravity: measured m/s^2 (9.78030 +- 0.00002), place (lat -34.9 alt 43), or "
              "standard",
              GravityAnswerText(o.gravity)};
  }
}

void WelcomeStep::Resume() {
  const WelcomeAnswers answers = ReadWelcomeAnswers(session_.model.inputs());
  ReadGravity(answers);
  ReadEquipment(answers);
  if (session_.model.done_steps().count(kWelcomeStepId) != 0) return;
  // The welcome was cut short: its answers so far are kept; ask the rest.
  while (question_ + 1 < Questions() && answers.Find(QuestionAt(question_).key)->has_value()) ++question_;
}

// The gravity the session recorded at its welcome; the options' when it has none (a session
// begun before the question was asked).
void WelcomeStep::ReadGravity(const WelcomeAnswers& answers) {
  if (!answers.gravity) return;
  const GravityAnswer g = ParseGravityAnswer(*answers.gravity);
  if (g.ok()) session_.gravity = g.gravity;
}

// The equipment the session recorded at its welcome (the procedure's, edited); the procedure's
// when it has none.
void WelcomeStep::ReadEquipment(const WelcomeAnswers& answers) {
  if (!answers.equipment) return;
  const EquipmentAnswer edited = ApplyEquipmentAnswer(*answers.equipment, session_.procedure.equipment);
  if (edited.ok()) session_.steps.set_equipment(edited.items);
}

std::string WelcomeStep::Check(const std::string& key, const std::string& value) {
  const ProcedureRequirements& need = session_.procedure.requirements;
  if (key == welcome_key::kDevice && value.empty() && need.device_serial)
    return "this procedure needs the device's serial number (on its label): type it";
  if (key == welcome_key::kOperator && value.empty() && need.operator_name)
    return "this procedure needs the operator's name: type it";
  if (key == welcome_key::kEquipment) return ApplyEquipmentAnswer(value, session_.procedure.equipment).error;
  if (key != welcome_key::kGravity) return "";
  const GravityAnswer g = ParseGravityAnswer(value);
  if (!g.ok()) return g.error;
  if (g.gravity.is_standard() && need.local_gravity)
    return "this procedure needs the local gravity, not the standard value: give a measured value "
           "(9.78030 +- 0.00002) or the place (lat -34.9 alt 43)";
  session_.gravity = g.gravity;
  return "";
}

void WelcomeStep::Handle(const Intent& intent) {
  if (intent.kind == IntentKind::kBack) {
    input_error_.clear();
    input_note_.clear();
    // Back from the first question: nothing is before it; say so rather than do nothing.
    if (question_ == 0) input_note_ = "This is the first question: there is nothing before it.";
    question_ = std::max(0, question_ - 1);
    return;
  }
  if (intent.kind != IntentKind::kSubmitText && intent.kind != IntentKind::kAccept) return;
  input_note_.clear();
  const Question question = QuestionAt(question_);
  std::string value = intent.kind == IntentKind::kSubmitText ? intent.text : "";
  if (IsBlank(value)) value = question.default_value;  // blanks only: the default, as for ""
  if (std::string why = Check(question.key, value); !why.empty()) {
    input_error_ = why;
    return;
  }
  input_error_.clear();
  // The gravity as it reads back (a resume parses it again).
  const std::string key = question.key;
  if (key == welcome_key::kGravity) value = GravityAnswerText(session_.gravity);
  session_.model.RecordInput(kWelcomeStepId, key, value);
  if (key == welcome_key::kEquipment) ReadEquipment(ReadWelcomeAnswers(session_.model.inputs()));
  if (question_ + 1 < Questions()) {
    ++question_;
    return;
  }
  session_.model.RecordStepDone(kWelcomeStepId, "ok");
  session_.sequence.ContinueFromFirstOpenStep();
}

void WelcomeStep::SetView(WizardView& v) const {
  const Question question = QuestionAt(question_);
  v.screen = WizardScreen::kWelcome;
  v.prompt = fmt::format("Welcome to {}.", session_.procedure.title);
  session_.bench_plan.Refresh(session_);  // the bench time the plan takes (bench_plan.h)
  if (const std::string plan = session_.bench_plan.WelcomeText(); !plan.empty()) v.prompt += " " + plan;
  if (!input_note_.empty()) v.prompt += " " + input_note_;
  v.input = InputRequest{question.key, question.label, question.default_value, input_error_};
  v.keys = {{"Enter", "accept"}, {"b", "back"}, {"q", "save and quit"}};
}

std::string WelcomeInputHelp(std::string_view key) {
  if (key == welcome_key::kDevice)
    return "Type the device's serial number, from its label; it goes in the report and the "
           "calibration file. An empty answer takes the default shown in brackets.";
  if (key == welcome_key::kOperator) return "Type your name, for the report. An empty answer takes the default.";
  if (key == welcome_key::kPlace)
    return "Type where the bench is (lab, room, bench), for the report. An empty answer takes "
           "the default.";
  if (key == welcome_key::kGravity)
    return "Type the local gravity: a measured value in m/s^2 with its uncertainty "
           "(9.78030 +- 0.00002), the place to compute it from (lat -34.9 alt 43: latitude in "
           "degrees, altitude in metres), or 'standard' (9.80665, a convention: a procedure that "
           "needs the local value refuses it).";
  return "";
}

}  // namespace accelcal
