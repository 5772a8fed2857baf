#include "line_mode_help.h"

#include <ostream>

#include <fmt/core.h>

#include "accelcal/app/wizard/step_help.h"

namespace accelcal::ui {

bool IsHelpRequest(const std::string& trimmed_line) {
  return trimmed_line == "?" || trimmed_line == "help";
}

void PrintLineModeHelp(const WizardView& view, std::ostream& out) {
  out << "  help:\n";
  for (const std::string& paragraph : StepHelp(view)) out << "  " << paragraph << '\n';
  out << "  Answers (each alone on a line):\n";
  for (const KeyHint& hint : view.keys) {
    const std::string answer = hint.key == "Enter" ? "(empty line)" : hint.key;
    out << fmt::format("    {:<13} {}\n", answer, hint.action);
  }
  out << fmt::format("    {:<13} {}\n", "? or help", "this help");
}

}  // namespace accelcal::ui
