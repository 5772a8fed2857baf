// The welcome (the session's first screen, before the procedure's steps): the device's serial
// number, the operator, the place, the local gravity (a measured value with its uncertainty, the
// place's latitude and altitude, or "standard" said explicitly: gravity_input.h) and, when the
// procedure lists some, the bench's equipment (equipment_input.h). Each answer is checked
// (a procedure may require the serial, the operator, the local gravity) and recorded as it is
// given; a welcome cut short resumes at its first unanswered question. b goes to the previous
// question.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "accelcal/app/wizard/step_controller.h"
#include "accelcal/app/wizard/wizard_session.h"
#include "accelcal/session/session_inputs.h"

namespace accelcal {

class WelcomeStep final : public StepController {
 public:
  explicit WelcomeStep(WizardSession& session) : session_(session) {}

  void Enter() override {}
  void Handle(const Intent& intent) override;
  void KeepAfterSkipDeclined() override {}
  // The session's gravity and equipment as the welcome recorded them (else the options' and the
  // procedure's), and the question to go on at when it was cut short.
  void Resume() override;
  void SetHeader(WizardView& v) const override { v.step_title = "Welcome"; }
  void SetView(WizardView& v) const override;
  // What the source's device holds (WizardOptions::device_lines), above the questions.
  void AddText(std::vector<std::string>& lines) const override;
  // A session resumed after its welcome: what the device holds now, and whether it is what the
  // session recorded when it began (a vehicle calibrated again in between says so).
  std::vector<std::string> DeviceResumeLines() const;

 private:
  // A question: its input key, label and default answer.
  struct Question {
    const char* key;
    std::string label;
    std::string default_value;
  };
  // device, operator, place, gravity, and the equipment when the procedure lists some.
  int Questions() const { return session_.procedure.equipment.empty() ? 4 : 5; }
  Question QuestionAt(int index) const;
  // Empty when `value` answers `key`; else why not.
  std::string Check(const std::string& key, const std::string& value);
  std::string CheckEquipment(const std::string& value);
  std::string DefaultAnswer(const Question& question) const;
  void ReadGravity(const WelcomeAnswers& answers);
  void ReadEquipment(const WelcomeAnswers& answers);
  // The session's equipment through the options' check_equipment (the lab's register).
  void CheckEquipmentWithLab();
  // The items as the session holds them; before the equipment is answered, those its question
  // offers (a virtual bench's lab's), which Enter keeps.
  std::vector<EquipmentItem> OfferedEquipment() const;
  void AddLabUnreachable(WizardView& v) const;
  // Records the device's lines with the answers (when there are some).
  void RecordDeviceLines();

  WizardSession& session_;
  int question_ = 0;
  std::string input_error_;  // why the last answer was refused
  std::string input_note_;   // said above the question (b at the first one)
  std::vector<std::string> equipment_warnings_;  // the lab's, listed on the welcome's questions
  std::string lab_unreachable_;                  // non-empty: the lab could not be reached (why)
  std::string examples_warned_;  // the equipment answer refused once for its example ids
};

// What to type at a question of the welcome (its input key), for the help on ?; empty for a key
// it does not ask or says nothing more about (the equipment's question says it all).
std::string WelcomeInputHelp(std::string_view key);

}  // namespace accelcal
