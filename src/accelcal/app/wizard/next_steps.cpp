#include "accelcal/app/wizard/next_steps.h"

#include <algorithm>

#include <fmt/core.h>
#include <fmt/format.h>

namespace accelcal {
namespace {

bool Contains(const std::vector<std::string>& ids, const std::string& id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// The session's steps that keep it from PASS: taken again (the fit left its run out) or skipped.
void AddSteps(const ReportInputs& in, const std::string& session, const std::vector<std::string>& left_out_by_fit,
              std::vector<std::string>* out) {
  if (!in.gaps) return;
  std::vector<std::string> again, skipped;
  for (const SessionGaps::Step& s : in.gaps->steps) {
    if (!s.required) continue;
    if (s.why == "skipped") skipped.push_back(fmt::format("'{}'", s.title));
    else again.push_back(fmt::format("'{}'", s.title));
  }
  const bool fit = std::any_of(in.gaps->steps.begin(), in.gaps->steps.end(),
                               [&](const SessionGaps::Step& s) { return Contains(left_out_by_fit, s.id); });
  if (!again.empty())
    out->push_back(fmt::format("take {} again{}: the wizard run again on this session (--session {}) "
                               "offers it first, and keeps the other captures",
                               fmt::join(again, ", "), fit ? ", mounted as asked" : "", session));
  if (!skipped.empty())
    out->push_back(fmt::format("a finished session takes no more steps: {} need{} a new session",
                               fmt::join(skipped, ", "), skipped.size() == 1 ? "s" : ""));
}

// The inputs `accelcal refit` corrects without a capture taken again.
void AddInputs(const ReportInputs& in, const std::string& session, std::vector<std::string>* out) {
  if (in.gaps)
    for (const std::string& what : in.gaps->identification)
      out->push_back(fmt::format("give the {0}: accelcal refit {1} --{2} '...'", what, session,
                                 what == "operator" ? "operator" : "device"));
  if (!UnidentifiedEquipment(in.equipment).empty())
    out->push_back(fmt::format("give each item of the bench its own id and calibration: accelcal refit {} "
                               "--equipment 'ruler id RUL-07 cal C-2291; turntable id TT-3 cal T-118'",
                               session));
  const Calibration& cal = in.calibration;
  if (cal.budget && !cal.budget->not_stated.empty())
    out->push_back(fmt::format("state the uncertainty of the {}: accelcal refit {} --equipment '... u ...'",
                               fmt::join(cal.budget->not_stated, ", "), session));
  const bool scale_found =
      std::any_of(cal.effects.begin(), cal.effects.end(),
                  [](const CalibrationEffect& e) { return TakesGravityErrorForItsOwn(e.name); }) ||
      (in.gaps && !in.gaps->gravity_ambiguity.empty());
  if (!scale_found) return;
  if (cal.gravity.is_standard())
    out->push_back(fmt::format("give the local gravity, measured or from the place: accelcal refit {} "
                               "--gravity 9.78030+-0.00002, or --latitude DEG --altitude M",
                               session));
  else
    out->push_back(fmt::format("check the turntable's speed (a calibrated tachometer) and radius (a calibrated "
                               "ruler) and the local gravity; give what you find: accelcal refit {} "
                               "--equipment 'turntable cal T-118; ruler cal C-2291' (or --gravity)",
                               session));
}

void AddLimits(const ReportModel& m, const std::string& session, std::vector<std::string>* out) {
  bool on_u = false, tolerance = false, fit = false;
  for (const LimitCheck& c : m.checks) {
    if (c.pass) continue;
    if (c.on_uncertainty) on_u = true;
    else if (!c.parameter.empty()) tolerance = true;
    else fit = true;
  }
  if (on_u)
    out->push_back(fmt::format("measure better what dominates U (said above), then give it to this session, "
                               "no capture taken again: accelcal refit {} --equipment 'ruler u 0.1 cal C-2291' "
                               "(or --gravity)", session));
  if (tolerance)
    out->push_back("a value is outside its tolerance (said above): the device does not conform as measured, "
                   "or U is too large to show that it does; a device outside its datasheet is repaired or "
                   "set aside");
  if (fit)
    out->push_back("the captures do not agree with one model: check the bench (level, mounting, nothing "
                   "knocking it) and calibrate again in a new session; the report's residuals show which "
                   "captures stand out");
}

}  // namespace

std::vector<std::string> NextSteps(const ReportInputs& in, const ReportModel& verdict, const std::string& session,
                                   const std::vector<std::string>& left_out_by_fit) {
  std::vector<std::string> out;
  if (verdict.verdict == Verdict::kPass) return out;
  AddSteps(in, session, left_out_by_fit, &out);
  AddInputs(in, session, &out);
  AddLimits(verdict, session, &out);
  return out;
}

}  // namespace accelcal
