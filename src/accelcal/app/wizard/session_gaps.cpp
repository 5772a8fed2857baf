#include "accelcal/app/wizard/session_gaps.h"

#include <fmt/core.h>

#include "accelcal/app/wizard/resume_summary.h"

namespace accelcal {
namespace {

// Why a capture step has no usable capture: its captures' left-out reasons.
std::string LeftOutWhy(const ProcedureStep& step, const SessionModel& model) {
  std::string why;
  for (const JournalCapture& c : model.captures()) {
    if (SessionModel::ProcedureStepOf(c.step_id) != step.id) continue;
    const std::string reason = model.LeftOutReason(c);
    if (!reason.empty()) why = fmt::format("its capture {} was left out: {}", c.capture.id, reason);
  }
  return why;
}

}  // namespace

SessionGaps CollectSessionGaps(const Procedure& procedure, const SessionModel& model) {
  SessionGaps gaps;
  const auto& done = model.done_steps();
  for (const ProcedureStep& s : procedure.steps) {
    const auto d = done.find(s.id);
    if (d != done.end() && d->second == "skipped") {
      gaps.steps.push_back({s.id, StepDisplayTitle(s), "skipped", s.required});
      continue;
    }
    if (!KeepsCapture(s.kind) || model.CaptureOf(s.id) != nullptr) continue;
    const std::string left_out = LeftOutWhy(s, model);
    if (!left_out.empty()) gaps.steps.push_back({s.id, StepDisplayTitle(s), left_out, s.required});
  }
  const WelcomeAnswers welcome = ReadWelcomeAnswers(model.inputs());
  if (procedure.requirements.device_serial && welcome.device.value_or("").empty())
    gaps.identification.push_back("device serial");
  if (procedure.requirements.operator_name && welcome.operator_name.value_or("").empty())
    gaps.identification.push_back("operator");
  return gaps;
}

std::vector<std::string> AddLeftOutByTheFit(const Procedure& procedure, const SessionModel& model,
                                            const Calibration& cal, SessionGaps* gaps) {
  std::vector<std::string> ids;
  for (const ProcedureStep& s : procedure.steps) {
    const JournalCapture* c = KeepsCapture(s.kind) ? model.CaptureOf(s.id) : nullptr;
    if (c == nullptr) continue;
    for (const CalibrationCapture& used : cal.captures) {
      if (used.id != c->capture.id || used.used) continue;
      const bool turntable = IsTurntableRunStep(s.kind);
      const std::string title =
          turntable ? fmt::format("{} at {:g} mm, {:g} rpm", s.title, c->capture.radius_m * 1000.0, c->capture.rpm)
                    : s.title;
      gaps->steps.push_back({s.id, title,
                             fmt::format("its capture {} was left out by the fit: {}", used.id,
                                         used.reason.empty() ? std::string("not stated") : used.reason),
                             s.required});
      ids.push_back(s.id);
    }
  }
  return ids;
}

}  // namespace accelcal
