#include "accelcal/app/wizard/step_registry.h"

#include <deque>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal {

// The built-in kinds, each defined in its controller's file (steps/*_step.cpp).
StepControllerKind LevelStepKind();
StepControllerKind StaticStepKind();
StepControllerKind TurntableStepKind();
StepControllerKind RecordStepKind();
StepControllerKind FitStepKind();
StepControllerKind DiagnosisStepKind();
StepControllerKind ReportStepKind();
StepControllerKind AnalysisStepKind();

namespace {

// A deque: the references ControllerKindOf hands out stay valid when a kind is added.
std::deque<StepControllerKind>& RegisteredControllers() {
  static std::deque<StepControllerKind> kinds = {
      LevelStepKind(), StaticStepKind(),    TurntableStepKind(), RecordStepKind(),
      FitStepKind(),   DiagnosisStepKind(), ReportStepKind(),    AnalysisStepKind(),
  };
  return kinds;
}

const StepControllerKind* FindController(StepKind kind) {
  for (const StepControllerKind& c : RegisteredControllers())
    if (c.kind == kind) return &c;
  return nullptr;
}

}  // namespace

const StepControllerKind& ControllerKindOf(StepKind kind) {
  const StepControllerKind* c = FindController(kind);
  if (c == nullptr)
    throw Error(fmt::format("the wizard has no controller for steps of kind '{}'", StepKindToString(kind)));
  return *c;
}

std::string StepInputHelp(std::string_view key) {
  for (const StepControllerKind& c : RegisteredControllers())
    if (c.input_help != nullptr)
      if (std::string help = c.input_help(key); !help.empty()) return help;
  return "";
}

// The kinds defined beside their controllers, one line each: KIND(the function of the kind's
// controller file that returns its StepKindDefinition). Adding a kind adds its line here.
#define ACCELCAL_STEP_KINDS(KIND) \
  KIND(RepeatStepKind)            \
  KIND(WriteBackStepKind)         \
  /* the list ends here */

#define ACCELCAL_DECLARE_STEP_KIND(definition) StepKindDefinition definition();
ACCELCAL_STEP_KINDS(ACCELCAL_DECLARE_STEP_KIND)
#undef ACCELCAL_DECLARE_STEP_KIND

void RegisterStepKinds() {
  static const bool registered = [] {
#define ACCELCAL_REGISTER_STEP_KIND(definition) \
  RegisterWizardStepKind(definition().info, definition().controller);
    ACCELCAL_STEP_KINDS(ACCELCAL_REGISTER_STEP_KIND)
#undef ACCELCAL_REGISTER_STEP_KIND
    return true;
  }();
  (void)registered;
}

StepKind RegisterWizardStepKind(const StepKindInfo& info, StepControllerKind controller) {
  const StepKind kind = RegisterStepKind(info);
  if (FindController(kind) == nullptr) {
    controller.kind = kind;
    RegisteredControllers().push_back(controller);
  }
  return kind;
}

}  // namespace accelcal
