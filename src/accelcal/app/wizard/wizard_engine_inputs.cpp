// The wizard engine's typed answers: the welcome (identification and the local gravity) and
// a turntable run's radius and speed.
#include <fmt/core.h>

#include "accelcal/app/wizard/equipment_input.h"
#include "accelcal/app/wizard/gravity_input.h"
#include "accelcal/app/wizard/quantity_input.h"
#include "accelcal/app/wizard/session_gaps.h"
#include "accelcal/app/wizard/session_settings.h"
#include "accelcal/app/wizard/wizard_engine.h"

namespace accelcal {

WizardEngine::WelcomeField WizardEngine::Welcome(int field) const {
  switch (field) {
    case 0: return {"device", "Device serial number", options_.default_device};
    case 1: return {"operator", "Operator", options_.default_operator};
    case 2: return {"place", "Place (lab, bench)", options_.default_place};
    case 4: {
      const EquipmentQuestionText q = EquipmentQuestion(procedure_.equipment, options_.default_equipment);
      return {"equipment", q.label, q.default_answer};
    }
    default:
      return {"gravity",
              "Local gravity: measured m/s^2 (9.78030 +- 0.00002), place (lat -34.9 alt 43), or "
              "standard",
              GravityAnswerText(options_.gravity)};
  }
}

// The equipment the session recorded at its welcome (the procedure's, edited); the procedure's
// when it has none.
void WizardEngine::ReadEquipment() { steps_.set_equipment(ReadSessionSettings(procedure_, model_).equipment); }

// Empty when `value` answers `key`; else why not.
std::string WizardEngine::CheckWelcomeAnswer(const std::string& key, const std::string& value) {
  const ProcedureRequirements& need = procedure_.requirements;
  if (key == "device" && value.empty() && need.device_serial)
    return "this procedure needs the device's serial number (on its label): type it";
  if (key == "operator" && value.empty() && need.operator_name)
    return "this procedure needs the operator's name: type it";
  if (key == "equipment") return ApplyEquipmentAnswer(value, procedure_.equipment).error;
  if (key != "gravity") return "";
  const GravityAnswer g = ParseGravityAnswer(value);
  if (!g.ok()) return g.error;
  if (g.gravity.is_standard() && need.local_gravity)
    return "this procedure needs the local gravity, not the standard value: give a measured value "
           "(9.78030 +- 0.00002) or the place (lat -34.9 alt 43)";
  gravity_ = g.gravity;
  return "";
}

void WizardEngine::HandleWelcome(const Intent& intent) {
  if (intent.kind == IntentKind::kBack) {
    input_error_.clear();
    input_note_.clear();
    // Back from the first question: nothing is before it; say so rather than do nothing.
    if (welcome_field_ == 0) input_note_ = "This is the first question: there is nothing before it.";
    welcome_field_ = std::max(0, welcome_field_ - 1);
    return;
  }
  if (intent.kind != IntentKind::kSubmitText && intent.kind != IntentKind::kAccept) return;
  input_note_.clear();
  const WelcomeField field = Welcome(welcome_field_);
  std::string value = intent.kind == IntentKind::kSubmitText ? intent.text : "";
  if (IsBlank(value)) value = field.default_value;  // blanks only: the default, as for ""
  if (std::string why = CheckWelcomeAnswer(field.key, value); !why.empty()) {
    input_error_ = why;
    return;
  }
  input_error_.clear();
  // The gravity as it reads back (a resume parses it again).
  if (std::string(field.key) == "gravity") value = GravityAnswerText(gravity_);
  if (std::string(field.key) == "equipment") value = EquipmentAnswerOver(field.default_value, value);
  model_.RecordInput(kWelcomeStepId, field.key, value);
  if (std::string(field.key) == "equipment") ReadEquipment();
  if (welcome_field_ + 1 < WelcomeFields()) {
    ++welcome_field_;
    return;
  }
  model_.RecordStepDone(kWelcomeStepId, "ok");
  AdvanceFrom(0);
}

// A value goes to the field its unit names, wherever the cursor is: "300 rpm" typed at the
// radius corrects the speed (the technician read "lower the speed" and typed a speed). The cursor
// stays; a note says what was taken. Blank text is empty: the field's default.
void WizardEngine::HandleTurntableInput(const Intent& intent) {
  if (intent.kind == IntentKind::kSkip) return AskSkip();
  if (intent.kind == IntentKind::kBack) {
    input_error_.clear();  // the refusal was about the field left
    input_note_.clear();
    return GoBack();
  }
  if (intent.kind != IntentKind::kAccept && intent.kind != IntentKind::kSubmitText) return;
  const bool radius = phase_ == Phase::kRadius;
  const std::string text =
      intent.kind == IntentKind::kSubmitText && !IsBlank(intent.text) ? intent.text : "";
  input_note_.clear();
  const TurntableField unit_field = FieldOfUnit(text);
  if (unit_field != TurntableField::kNone && (unit_field == TurntableField::kRadius) != radius)
    return CorrectOtherTurntableField(text, unit_field == TurntableField::kRadius);
  const double fallback = radius ? radius_m_ : rpm_;
  const QuantityResult q = text.empty() ? QuantityResult{fallback, ""}
                                        : (radius ? ParseRadius(text) : ParseRpm(text));
  if (!q.ok()) {
    input_error_ = q.error;
    return;
  }
  input_error_.clear();
  if (radius) {
    radius_m_ = q.value;
    phase_ = Phase::kRpm;
    return;
  }
  CheckTurntablePlanAndPlace(q.value);
}

void WizardEngine::CorrectOtherTurntableField(const std::string& text, bool to_radius) {
  const QuantityResult q = to_radius ? ParseRadius(text) : ParseRpm(text);
  if (!q.ok()) {
    input_error_ = q.error;
    return;
  }
  input_error_.clear();
  (to_radius ? radius_m_ : rpm_) = q.value;
  input_note_ = to_radius
                    ? fmt::format("Radius set to {:g} mm; now the speed.", q.value * 1000.0)
                    : fmt::format("Speed set to {:g} rpm; now the radius.", q.value);
}

// The plan (radius_m_ with `rpm`) against the accelerometer's range. A refused speed never
// becomes the default: the default goes back to the procedure's, and the cursor stays on the
// speed, where the technician types next (or types a radius there: see above).
void WizardEngine::CheckTurntablePlanAndPlace(double rpm) {
  TurntableSetup setup;
  setup.radius_m = radius_m_;
  setup.rpm = rpm;
  setup.radial_axis = SensorAxisVector(step().radial_axis);
  setup.up_axis = SensorAxisVector(step().up_axis);
  TurntableStabilityOptions o;
  o.gravity_mps2 = gravity_.gravity_mps2;
  const std::string why = CheckTurntableAgainstRange(setup, procedure_.range_g, procedure_.nominal,
                                                     procedure_.adc_range, o);
  if (!why.empty()) {
    input_error_ = why;
    rpm_ = step().rpm;
    return;
  }
  rpm_ = rpm;
  EnterPlace();
}

}  // namespace accelcal
