#include "accelcal/app/wizard/session_clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include <fmt/core.h>

namespace accelcal {
namespace {

double SystemWallS() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

double MaxFinite(double a, double b) {
  if (!std::isfinite(a)) return b;
  if (!std::isfinite(b)) return a;
  return std::max(a, b);
}

}  // namespace

SessionClock::SessionClock(const SessionModel& model, std::function<double()> wall_now_s)
    : wall_now_s_(wall_now_s ? std::move(wall_now_s) : SystemWallS) {
  for (const JournalCapture& c : model.captures()) last_t_s_ = MaxFinite(last_t_s_, c.capture.stats().t_last_s);
  for (const std::string& step : model.RecordSteps()) {
    const RecordSummary r = model.RecordSummaryOf(step);
    last_t_s_ = MaxFinite(last_t_s_, r.t_last_s);
    last_wall_s_ = MaxFinite(last_wall_s_, r.last_wall_end_s);
  }
  const auto clock = model.inputs().find(kClockStep);
  if (clock == model.inputs().end()) return;
  for (const auto& [key, value] : clock->second) {
    if (key.rfind(session_clock_key::kResumePrefix, 0) == 0) ++resumes_;
    if (key != session_clock_key::kLastCapture) continue;
    std::istringstream in(value);
    double t = kNaN, wall = kNaN;
    if (in >> t >> wall) last_wall_s_ = MaxFinite(last_wall_s_, wall);
  }
}

void SessionClock::Shift(std::vector<Sample>* chunk, SessionModel& model) {
  if (chunk->empty()) return;
  if (!decided_) {
    decided_ = true;
    const double first_t_s = chunk->front().t_s;
    if (std::isfinite(last_t_s_) && !(first_t_s > last_t_s_)) {
      const double wall_gap_s = wall_now_s_() - last_wall_s_;
      const double gap_s = std::max(kMinGapS, std::isfinite(wall_gap_s) ? wall_gap_s : 0.0);
      offset_s_ = last_t_s_ + gap_s - first_t_s;
      note_ = fmt::format("The session clock goes on at t = {:.2f} s, {:.1f} s after the last "
                          "sample recorded (t = {:.2f} s; the gap measured on the computer's clock).",
                          first_t_s + offset_s_, gap_s, last_t_s_);
      model.RecordInput(kClockStep, fmt::format("{}{}", session_clock_key::kResumePrefix, resumes_ + 1),
                        fmt::format("t {:.6f} s -> {:.6f} s, a gap of {:.3f} s on the computer's clock",
                                    last_t_s_, first_t_s + offset_s_, gap_s));
    }
  }
  if (offset_s_ == 0.0) return;
  for (Sample& s : *chunk) s.t_s += offset_s_;
}

std::optional<double> SessionClock::ResumedAtS(const std::string& resume_value) {
  // "t 1017.210000 s -> 1059.300000 s, a gap of ..." (Shift's words)
  std::istringstream in(resume_value);
  std::string t, s_before, arrow;
  double before_s = kNaN, after_s = kNaN;
  if (!(in >> t >> before_s >> s_before >> arrow >> after_s) || t != "t" || arrow != "->" ||
      !std::isfinite(after_s))
    return std::nullopt;
  return after_s;
}

void SessionClock::MarkCapture(double t_last_s, SessionModel& model) {
  last_t_s_ = MaxFinite(last_t_s_, t_last_s);
  last_wall_s_ = wall_now_s_();
  model.RecordInput(kClockStep, session_clock_key::kLastCapture,
                    fmt::format("{:.6f} {:.6f}", t_last_s, last_wall_s_));
}

}  // namespace accelcal
