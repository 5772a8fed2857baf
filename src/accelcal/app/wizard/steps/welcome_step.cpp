#include "accelcal/app/wizard/steps/welcome_step.h"

#include <algorithm>
#include <utility>

#include <fmt/core.h>
#include <fmt/format.h>

#include "accelcal/app/wizard/equipment_input.h"
#include "accelcal/app/wizard/gravity_input.h"
#include "accelcal/app/wizard/quantity_input.h"
#include "accelcal/app/wizard/session_settings.h"
#include "accelcal/session/session_inputs.h"

namespace accelcal {

WelcomeStep::Question WelcomeStep::QuestionAt(int index) const {
  const WizardOptions& o = session_.options;
  switch (index) {
    case 0: return {welcome_key::kDevice, "Device serial number", o.default_device};
    case 1: return {welcome_key::kOperator, "Operator", o.default_operator};
    case 2: return {welcome_key::kPlace, "Place (lab, bench)", o.default_place};
    case 4: {
      // The procedure's equipment, or the lab's the options offer (the virtual bench's).
      const EquipmentQuestionText q = EquipmentQuestion(session_.procedure.equipment, o.default_equipment);
      return {welcome_key::kEquipment, q.label, q.default_answer};
    }
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
  CheckEquipmentWithLab();
  // The welcome was cut short: its answers so far are kept; ask the rest.
  while (question_ + 1 < Questions() && answers.Find(QuestionAt(question_).key)->has_value()) ++question_;
}

// The gravity the session recorded at its welcome; the options' when it has none (a session
// begun before the question was asked). Read as `accelcal refit` reads it (session_settings.h).
void WelcomeStep::ReadGravity(const WelcomeAnswers& answers) {
  if (const std::optional<GravitySpec> g = RecordedGravity(answers)) session_.gravity = *g;
}

// The equipment the session recorded at its welcome (the procedure's, edited); the procedure's
// when it has none.
void WelcomeStep::ReadEquipment(const WelcomeAnswers& answers) {
  session_.steps.set_equipment(RecordedEquipment(answers, session_.procedure));
}

// The items as the session holds them (the procedure's, or as the equipment answer edited them);
// before that answer, the items its default offers (a virtual bench's lab's), which Enter keeps.
std::vector<EquipmentItem> WelcomeStep::OfferedEquipment() const {
  std::vector<EquipmentItem> items = session_.steps.equipment();
  const WelcomeAnswers answers = ReadWelcomeAnswers(session_.model.inputs());
  const std::optional<std::string>* answered = answers.Find(welcome_key::kEquipment);
  if ((answered == nullptr || !answered->has_value()) && !session_.options.default_equipment.empty()) {
    EquipmentAnswer offered = ApplyEquipmentAnswer(session_.options.default_equipment, items);
    if (offered.ok()) items = std::move(offered.items);
  }
  return items;
}

void WelcomeStep::CheckEquipmentWithLab() {
  if (!session_.options.check_equipment) return;
  const std::vector<EquipmentItem> items = OfferedEquipment();
  WelcomeLabCheck check = session_.options.check_equipment(items);
  equipment_warnings_ = std::move(check.warnings);
  lab_unreachable_ = std::move(check.unreachable);
}

// The lab out of reach, in the bench's words: what is not done, that the session goes on, and
// what becomes of it (the wizard's end tries the lab again; else the session waits on this bench
// for `accelcal lab publish`, app/lab_publish.h). libpq's reason last, for whoever fixes it.
void WelcomeStep::AddLabUnreachable(WizardView& v) const {
  v.lines.push_back("The lab's register cannot be reached, so the equipment's calibration dates are not checked.");
  v.lines.push_back(
      "The session goes on here and is kept on this bench: at its end it is sent to the lab if the "
      "lab can be reached then, else it waits for `accelcal lab publish`.");
  v.lines.push_back("  (" + lab_unreachable_ + ")");
}

std::string WelcomeStep::Check(const std::string& key, const std::string& value) {
  const ProcedureRequirements& need = session_.procedure.requirements;
  if (key == welcome_key::kDevice && value.empty() && need.device_serial)
    return "this procedure needs the device's serial number (on its label): type it";
  if (key == welcome_key::kOperator && value.empty() && need.operator_name)
    return "this procedure needs the operator's name: type it";
  if (key == welcome_key::kEquipment) return CheckEquipment(value);
  if (key != welcome_key::kGravity) return "";
  const GravityAnswer g = ParseGravityAnswer(value);
  if (!g.ok()) return g.error;
  if (g.gravity.is_standard() && need.local_gravity)
    return "this procedure needs the local gravity, not the standard value: give a measured value "
           "(9.78030 +- 0.00002) or the place (lat -34.9 alt 43)";
  session_.gravity = g.gravity;
  return "";
}

// A procedure that states limits issues a certificate: the bench's items must be its own. The
// procedure's example ids are refused once, with what to type; the same answer again goes on
// (the verdict then says INCOMPLETE: equipment not identified).
std::string WelcomeStep::CheckEquipment(const std::string& value) {
  const Procedure& p = session_.procedure;
  if (std::string error = ApplyEquipmentAnswer(value, p.equipment).error; !error.empty()) return error;
  const std::string recorded = EquipmentAnswerOver(QuestionAt(question_).default_value, value);
  const std::vector<std::string> examples = UnidentifiedEquipment(ApplyEquipmentAnswer(recorded, p.equipment).items);
  if (!p.limits.Any() || examples.empty() || value == examples_warned_) return "";
  examples_warned_ = value;
  return fmt::format("this procedure issues a certificate, and {} {} not your bench's own: type each "
                     "item's id and calibration (ruler id RUL-07 cal C-2291; turntable id TT-3 cal T-118), "
                     "or Enter again to go on without them (the verdict will be INCOMPLETE: equipment not "
                     "identified)",
                     fmt::join(examples, ", "), examples.size() == 1 ? "is" : "are");
}

// What Enter answers: the question's default; at the equipment after its example ids were
// refused, the answer refused (Enter again goes on with it, not back to the default).
std::string WelcomeStep::DefaultAnswer(const Question& question) const {
  if (question.key == welcome_key::kEquipment && !examples_warned_.empty()) return examples_warned_;
  return question.default_value;
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
  if (IsBlank(value)) value = DefaultAnswer(question);  // blanks only: the default, as for ""
  if (std::string why = Check(question.key, value); !why.empty()) {
    input_error_ = why;
    return;
  }
  input_error_.clear();
  // The gravity as it reads back (a resume parses it again).
  const std::string key = question.key;
  if (key == welcome_key::kGravity) value = GravityAnswerText(session_.gravity);
  // An edit applies to the equipment the question showed (the offered lab's, on the virtual bench).
  if (key == welcome_key::kEquipment) value = EquipmentAnswerOver(question.default_value, value);
  session_.model.RecordInput(kWelcomeStepId, key, value);
  if (key == welcome_key::kEquipment) {
    ReadEquipment(ReadWelcomeAnswers(session_.model.inputs()));
    CheckEquipmentWithLab();
  }
  if (question_ + 1 < Questions()) {
    ++question_;
    return;
  }
  // What the lab still warns of (the items as answered) stays on the next screen until a key.
  if (!equipment_warnings_.empty())
    session_.screen.notice = fmt::format("Equipment: {}", fmt::join(equipment_warnings_, "; "));
  RecordDeviceLines();
  session_.model.RecordStepDone(kWelcomeStepId, "ok");
  session_.sequence.ContinueFromFirstOpenStep();
}

void WelcomeStep::SetView(WizardView& v) const {
  const Question question = QuestionAt(question_);
  v.screen = WizardScreen::kWelcome;
  v.prompt = fmt::format("Welcome to {}.", session_.procedure.title);
  // The bench time the plan takes (bench_plan.h), with the equipment Enter keeps.
  const std::vector<EquipmentItem> offered = OfferedEquipment();
  session_.bench_plan.Refresh(session_, &offered);
  if (const std::string plan = session_.bench_plan.WelcomeText(); !plan.empty()) v.prompt += " " + plan;
  if (!input_note_.empty()) v.prompt += " " + input_note_;
  v.input = InputRequest{question.key, question.label, DefaultAnswer(question), input_error_};
  v.keys = {{"Enter", "accept"}, {"b", "back"}, {"q", "save and quit"}};
  if (!lab_unreachable_.empty()) AddLabUnreachable(v);
  if (equipment_warnings_.empty()) return;
  v.lines.push_back("The lab's equipment register warns (the equipment question can name other items):");
  for (const std::string& warning : equipment_warnings_) v.lines.push_back("  " + warning);
}

void WelcomeStep::AddText(std::vector<std::string>& lines) const {
  const std::vector<std::string>& device = session_.options.device_lines;
  if (device.empty()) return;
  lines.push_back("The device's own calibration, as it holds it now:");
  for (const std::string& line : device) lines.push_back("  " + line);
}

std::vector<std::string> WelcomeStep::DeviceResumeLines() const {
  const std::vector<std::string>& device = session_.options.device_lines;
  if (device.empty()) return {};
  std::vector<std::string> lines;
  AddText(lines);
  const auto welcome = session_.model.inputs().find(kWelcomeStepId);
  if (welcome == session_.model.inputs().end()) return lines;
  const auto recorded = welcome->second.find(welcome_key::kDeviceCalibration);
  if (recorded != welcome->second.end() && recorded->second != fmt::format("{}", fmt::join(device, "\n"))) {
    lines.push_back("It is not what the device held when the session began:");
    const std::string& text = recorded->second;
    for (size_t start = 0, end = 0; start <= text.size(); start = end + 1) {
      end = std::min(text.find('\n', start), text.size());
      lines.push_back("  " + text.substr(start, end - start));
    }
  }
  return lines;
}

void WelcomeStep::RecordDeviceLines() {
  const std::vector<std::string>& device = session_.options.device_lines;
  if (!device.empty())
    session_.model.RecordInput(kWelcomeStepId, welcome_key::kDeviceCalibration, fmt::format("{}", fmt::join(device, "\n")));
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
