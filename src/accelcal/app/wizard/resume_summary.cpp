#include "accelcal/app/wizard/resume_summary.h"

#include <fmt/core.h>

#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/base/duration_text.h"

namespace accelcal {
namespace {

// "done (capture 7)", "done (capture 7; capture 3 taken again, superseded)", "left out, ...".
std::string CaptureStepState(const ProcedureStep& step, const SessionModel& model) {
  const JournalCapture* current = model.CaptureOf(step.id);
  std::string superseded;
  bool left_out = false;
  for (const JournalCapture& c : model.captures()) {
    if (SessionModel::ProcedureStepOf(c.step_id) != step.id) continue;
    if (c.superseded()) superseded += fmt::format("; capture {} taken again, superseded", c.capture.id);
    if (!model.LeftOutReason(c).empty()) left_out = true;
  }
  if (current != nullptr) return fmt::format("done (capture {}{})", current->capture.id, superseded);
  return left_out ? "left out, to be captured again" : "";
}

}  // namespace

std::string StepDisplayTitle(const ProcedureStep& step) {
  const StepControllerKind& kind = ControllerKindOf(step.kind);
  return kind.display_title != nullptr ? kind.display_title(step) : step.title;
}

std::vector<std::string> ResumeSummaryLines(const Procedure& procedure, const SessionModel& model,
                                            const std::string& welcome_id) {
  std::vector<std::string> lines;
  const std::map<std::string, std::string>& done = model.done_steps();
  if (done.count(welcome_id) != 0) lines.push_back("  Welcome: done");
  for (const ProcedureStep& s : procedure.steps) {
    const std::string title = StepDisplayTitle(s);
    // A capture first: a step skipped and then captured after b is done.
    if (const std::string state = CaptureStepState(s, model); !state.empty()) {
      lines.push_back(fmt::format("  {}: {}", title, state));
      continue;
    }
    const auto d = done.find(s.id);
    if (d != done.end()) {
      lines.push_back(fmt::format("  {}: {}", title, d->second == "skipped" ? "skipped" : "done"));
      continue;
    }
    const RecordSummary r = model.RecordSummaryOf(s.id);
    if (r.num_chunks > 0)
      lines.push_back(fmt::format("  {}: partly recorded ({} recorded over {}, {} chunks)", title,
                                  FormatLongDuration(r.recorded_s()), FormatLongDuration(r.span_s()),
                                  r.num_chunks));
  }
  return lines;
}

}  // namespace accelcal
