#include "accelcal/app/wizard/time_estimate.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/app/wizard/step_registry.h"

namespace accelcal {

// Each kind's controller knows its step's time (step_registry.h).
double StepEstimateS(const ProcedureStep& step, const TimeAllowances& a) {
  return ControllerKindOf(step.kind).estimate_s(step, a);
}

double RemainingEstimateS(const Procedure& procedure, int first,
                          const std::function<bool(const ProcedureStep&)>& done,
                          const TimeAllowances& allowances) {
  double total_s = 0.0;
  const int n = static_cast<int>(procedure.steps.size());
  for (int i = std::max(first, 0); i < n; ++i) {
    const ProcedureStep& s = procedure.steps[static_cast<size_t>(i)];
    if (!done(s)) total_s += StepEstimateS(s, allowances);
  }
  return total_s;
}

std::string FormatEstimate(double seconds) {
  if (!std::isfinite(seconds)) return "unknown";
  if (seconds < 10.0) return "under 10 s";
  if (seconds < 90.0) return fmt::format("about {:.0f} s", std::round(seconds / 10.0) * 10.0);
  if (seconds < 90.0 * 60.0) return fmt::format("about {:.0f} min", std::round(seconds / 60.0));
  return fmt::format("about {:.1f} h", seconds / 3600.0);
}

namespace {

std::string SessionPart(double session_left_s) {
  if (!std::isfinite(session_left_s)) return "";
  return fmt::format("session: {} left (estimate)", FormatEstimate(session_left_s));
}

std::string Seconds(double s) { return fmt::format("{:.0f} s", std::round(std::max(s, 0.0))); }

}  // namespace

std::string CaptureTimeText(double capture_s, double capture_left_s, double give_up_in_s,
                            double session_left_s) {
  std::string text = std::isfinite(capture_left_s)
                         ? Seconds(capture_left_s) + " left of this capture"
                         : fmt::format("this capture takes {:g} s once the sensor is still", capture_s);
  if (std::isfinite(give_up_in_s)) text += "; gives up in " + Seconds(give_up_in_s);
  if (const std::string s = SessionPart(session_left_s); !s.empty()) text += "; " + s;
  return text;
}

std::string WaitingTimeText(double capture_s, double timeout_s, double session_left_s) {
  std::string text;
  if (std::isfinite(capture_s))
    text = fmt::format("this capture takes {:g} s once the sensor is still (gives up after {:g} s)",
                       capture_s, timeout_s);
  if (const std::string s = SessionPart(session_left_s); !s.empty()) text += (text.empty() ? "" : "; ") + s;
  return text;
}

std::string LastStepTimeText() { return "session: this is the last step; the session ends when you continue"; }

}  // namespace accelcal
