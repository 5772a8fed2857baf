// The wizard's controller of each step kind (step_controller.h), one registration each: how to
// make it for a step, the step's time estimate, its title in a summary and the help of its
// questions. What a kind is (its name, what it acquires, its fields in the procedure file) is
// the step-kind table's (session/step_kind.h). The built-in kinds are listed in
// step_registry.cpp, one line each; RegisterWizardStepKind adds a kind at run time (a test's
// example kind).
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "accelcal/app/wizard/time_estimate.h"
#include "accelcal/session/procedure.h"

namespace accelcal {

class StepController;
struct WizardSession;

struct StepControllerKind {
  StepKind kind = StepKind::kStatic;
  // The controller of `step` (a step of this kind) in `session`; both outlive it.
  std::unique_ptr<StepController> (*make)(const ProcedureStep& step, WizardSession& session) = nullptr;
  // The step from its start: its capture or record length plus its handling, s.
  double (*estimate_s)(const ProcedureStep& step, const TimeAllowances& allowances) = nullptr;
  // The step's title as the technician reads it in a summary; nullptr: its title.
  std::string (*display_title)(const ProcedureStep& step) = nullptr;
  // What to type at a question the step asks (InputRequest::key `key`), for the help on ?;
  // empty for a key it does not ask. nullptr: it asks none.
  std::string (*input_help)(std::string_view key) = nullptr;
};

// StepControllerKind::make for a controller class `C` made from its step and the session.
template <typename C>
std::unique_ptr<StepController> MakeStepController(const ProcedureStep& step, WizardSession& session) {
  return std::make_unique<C>(step, session);
}

// Throws accelcal::Error for a kind that has no controller.
const StepControllerKind& ControllerKindOf(StepKind kind);
// The help of the question `key` from the kind that asks it; empty when none does.
std::string StepInputHelp(std::string_view key);

// Adds a kind: its row in the step-kind table (RegisterStepKind) and its controller (`controller`'s
// kind is set to the row's). A name already in the table keeps its row (and its controller when
// it has one); its kind is returned.
StepKind RegisterWizardStepKind(const StepKindInfo& info, StepControllerKind controller);

// A kind defined beside its controller (steps/<kind>_step.cpp, a function returning this): its
// row of the step-kind table and its controller, registered together by one line of
// step_registry.cpp's list (ARCHITECTURE.md, "How to add a step kind").
struct StepKindDefinition {
  StepKindInfo info;
  StepControllerKind controller;  // its `kind` is set when registered
};

// Registers every kind of step_registry.cpp's list. The procedure reader (io, below the wizard)
// knows a kind only once it is registered: every program that reads a procedure calls this at
// its start (ui/main.cpp, the test programs' main), before anything else. Calling it again does
// nothing.
void RegisterStepKinds();

}  // namespace accelcal
