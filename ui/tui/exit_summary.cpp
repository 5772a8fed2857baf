#include "tui/exit_summary.h"

#include <ostream>

namespace accelcal::ui {

void PrintExitSummary(const WizardView& view, std::ostream& out) {
  if (!view.problem.empty()) out << "problem: " << view.problem << '\n';
  if (!view.prompt.empty()) out << view.prompt << '\n';
  // The final screen's lines are its summary (verdict, numbers, report paths).
  if (view.finished && !view.verdict.empty())
    for (const std::string& line : view.lines) out << "  " << line << '\n';
  out.flush();
}

}  // namespace accelcal::ui
