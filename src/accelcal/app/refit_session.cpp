#include "accelcal/app/refit_session.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <string>

#include <fmt/core.h>
#include <fmt/format.h>

#include "accelcal/app/calibration_input.h"
#include "accelcal/app/wizard/calibration_steps.h"
#include "accelcal/app/wizard/equipment_input.h"
#include "accelcal/app/wizard/gravity_input.h"
#include "accelcal/app/wizard/session_gaps.h"
#include "accelcal/app/wizard/session_settings.h"
#include "accelcal/base/error.h"
#include "accelcal/base/utc_time.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/session/session_inputs.h"

namespace accelcal {
namespace {

using Inputs = SessionInputs;

// The welcome's answer kept under `key` (a welcome_key, session_inputs.h); "" when none.
std::string WelcomeInput(const Inputs& inputs, const char* key) {
  const WelcomeAnswers answers = ReadWelcomeAnswers(inputs);
  const std::optional<std::string>* answer = answers.Find(key);
  return answer != nullptr && *answer ? **answer : "";
}

// The refit steps of `inputs` by their number: "refit 1", "refit 2", ... ("refit 10" after 9).
std::map<int, const std::map<std::string, std::string>*> RefitSteps(const Inputs& inputs) {
  std::map<int, const std::map<std::string, std::string>*> out;
  for (const auto& [step, values] : inputs)
    if (step.rfind(kRefitStepPrefix, 0) == 0)
      out[std::atoi(step.c_str() + std::char_traits<char>::length(kRefitStepPrefix))] = &values;
  return out;
}

// A corrected welcome input: refused as the welcome refuses it; empty when it is not a change.
struct Change {
  std::string key;     // the welcome's input key
  std::string before;  // as recorded ("" when none)
  std::string after;
};

std::vector<Change> Changes(const Inputs& inputs, const Procedure& procedure, const RefitRequest& r) {
  std::vector<Change> out;
  const auto add = [&](const char* key, const std::string& after) {
    const std::string before = WelcomeInput(inputs, key);
    if (after != before) out.push_back({key, before, after});
  };
  const ProcedureRequirements& need = procedure.requirements;
  if (r.gravity) {
    if (r.gravity->is_standard() && need.local_gravity)
      throw Error("this procedure needs the local gravity, not the standard value: give a measured value "
                  "(--gravity 9.78030+-0.00002) or the place (--latitude -34.9 --altitude 43)");
    add(welcome_key::kGravity, GravityAnswerText(*r.gravity));
  }
  if (r.equipment_answer) {
    // An edit applies to the session's equipment, as at the welcome.
    const std::string before = WelcomeInput(inputs, welcome_key::kEquipment);
    const std::string after = EquipmentAnswerOver(before.empty() ? "keep" : before, *r.equipment_answer);
    if (std::string why = ApplyEquipmentAnswer(after, procedure.equipment).error; !why.empty())
      throw Error("--equipment: " + why);
    add(welcome_key::kEquipment, after);
  }
  if (r.device) {
    if (r.device->empty() && need.device_serial) throw Error("this procedure needs the device's serial number");
    add(welcome_key::kDevice, *r.device);
  }
  if (r.operator_name) {
    if (r.operator_name->empty() && need.operator_name) throw Error("this procedure needs the operator's name");
    add(welcome_key::kOperator, *r.operator_name);
  }
  if (r.place) add(welcome_key::kPlace, *r.place);
  return out;
}

std::string ChangeText(const Change& c) {
  return fmt::format("{}: {} -> {}", c.key, c.before.empty() ? "(none)" : c.before, c.after.empty() ? "(none)" : c.after);
}

}  // namespace

RefitOutcome RefitSession(SessionJournal& journal, const Procedure& procedure, const RefitRequest& request) {
  if (!journal.Result())
    throw Error(fmt::format("session {} has no calibration yet: run the wizard to finish it (refit corrects "
                            "a finished session)", request.session_name));
  SessionModel model(journal);
  RefitOutcome out;
  out.earlier_results = journal.ResultCount();
  const std::vector<Change> changes = Changes(model.inputs(), procedure, request);
  for (const Change& c : changes) out.changes.push_back(ChangeText(c));

  // The session's settings with the corrections, checked before anything is recorded: a fit
  // that is not usable records nothing.
  SessionSettings settings = ReadSessionSettings(procedure, model);
  GravitySpec gravity = settings.gravity.value_or(GravitySpec::Standard());
  if (request.gravity) gravity = *request.gravity;
  for (const Change& c : changes)
    if (c.key == welcome_key::kEquipment) settings.equipment = ApplyEquipmentAnswer(c.after, procedure.equipment).items;
  std::unique_ptr<WizardOutputs> outputs =
      request.report_beside.empty() ? nullptr : MakeOutputsBesideSession(request.report_beside);
  CalibrationSteps steps(procedure, model, gravity, request.session_name, outputs.get());
  steps.set_equipment(settings.equipment);
  steps.set_noise_floor(settings.lowered_floor);
  if (const StepOutcome fit = steps.Fit(); !fit.problem.empty()) throw Error("refit: " + fit.problem);

  // What changed, when; then the welcome's inputs take the corrected values.
  out.refit_step = fmt::format("{}{}", kRefitStepPrefix, RefitSteps(model.inputs()).size() + 1);
  model.RecordInput(out.refit_step, refit_key::kAt, request.now_utc);
  for (size_t i = 0; i < out.changes.size(); ++i)
    model.RecordInput(out.refit_step, fmt::format("{}{}", refit_key::kChangePrefix, i + 1), out.changes[i]);
  for (const Change& c : changes) model.RecordInput(kWelcomeStepId, c.key, c.after);

  ReportMeta meta;
  meta.session_path = request.report_beside;
  meta.procedure = procedure.title;
  meta.source = request.source;
  meta.date_utc = request.now_utc;
  meta.history = SessionHistory(model, out.earlier_results);
  const StepOutcome report = steps.Report(settings.adopt_effects, meta, CollectSessionGaps(procedure, model));
  if (!report.problem.empty()) throw Error("refit: " + report.problem);
  model.RecordStepDone(out.refit_step, "recorded");
  if (const FinalSummary* summary = steps.final_summary()) out.summary = *summary;
  return out;
}

namespace {

// The procedure the session ran: the one given, else the default when its title is the session's.
Procedure SessionProcedure(const RefitFileRequest& r, const SessionInfo& info) {
  if (!r.procedure_path.empty()) {
    Procedure p = LoadProcedure(r.procedure_path);
    if (!p.IsTitled(info.procedure))
      throw Error(fmt::format("session {} ran the procedure \"{}\", not \"{}\" ({})", info.path, info.procedure,
                              p.title, r.procedure_path));
    return p;
  }
  Procedure shipped = LoadProcedure(r.default_procedure_path);
  if (!shipped.IsTitled(info.procedure))
    throw Error(fmt::format("session {} ran the procedure \"{}\": give its file with --procedure", info.path,
                            info.procedure));
  return shipped;
}

}  // namespace

RefitFileOutcome RefitSessionFile(const RefitFileRequest& request) {
  const std::unique_ptr<SessionStore> store = OpenSessionToChange(request.input);
  const SessionInfo info = store->Info();
  // A fixture's session: the store's Result() is the first sensor's alone, which a refit here
  // would fit without the fixture (its radius, the plate's placement: sensor_batch.h) and not
  // the lead the wizard refits (FixtureJournal); never a result that disagrees with the batch
  // the session ended with.
  if (const std::optional<Fixture> sensors = store->Sensors(); sensors && sensors->sensors.size() > 1)
    throw Error(fmt::format("session {} holds {} sensors on a fixture: refit corrects a session of one "
                            "sensor; each sensor of this one was calibrated at its end and is reported with "
                            "`accelcal report {} --sensor N` (a refit of every sensor is not built yet)",
                            info.path, sensors->sensors.size(), info.path));
  const Procedure procedure = SessionProcedure(request, info);
  RefitRequest refit = request.corrections;
  refit.session_name = info.path;
  refit.report_beside = info.path;
  refit.source = info.source;
  refit.now_utc = UtcNowIso8601();
  RefitFileOutcome out;
  out.path = info.path;
  out.refit = RefitSession(*store, procedure, refit);
  return out;
}

std::vector<std::string> SessionHistory(const SessionJournal& journal, int earlier_results) {
  const Inputs inputs = journal.Inputs();
  std::vector<std::string> out;
  for (const auto& [n, values] : RefitSteps(inputs)) {
    std::vector<std::string> changes;
    std::string at;
    for (const auto& [key, value] : *values) {
      if (key == refit_key::kAt) at = value;
      else if (key.rfind(refit_key::kChangePrefix, 0) == 0) changes.push_back(value);
    }
    out.push_back(fmt::format("refit {} ({}): {}", n, at.empty() ? "time not recorded" : at,
                              changes.empty() ? "no input changed" : fmt::format("{}", fmt::join(changes, "; "))));
  }
  if (earlier_results > 0)
    out.push_back(fmt::format("{} earlier calibration{} kept in the session; this is the latest",
                              earlier_results, earlier_results == 1 ? " is" : "s are"));
  return out;
}

std::vector<std::string> UnusedResumeFlags(const SessionJournal& journal, const std::string& session,
                                           const std::string& gravity_flag, const std::string& place_flag) {
  const Inputs inputs = journal.Inputs();
  std::vector<std::string> out;
  // A session still under way has no calibration to refit yet: the command is for its end.
  const std::string when = journal.ResultCount() > 0 ? "" : ", once the session is finished";
  const std::string gravity = WelcomeInput(inputs, welcome_key::kGravity);
  if (!gravity_flag.empty() && !gravity.empty())
    out.push_back(fmt::format("{} ignored: this session's gravity was recorded at its welcome ({}); to "
                              "calibrate it with another{}: accelcal refit {} {}",
                              gravity_flag, gravity, when, session, gravity_flag));
  if (!place_flag.empty() && ReadWelcomeAnswers(inputs).place)
    out.push_back(fmt::format("--place {} ignored: this session's place was recorded at its welcome ({}); "
                              "to change it{}: accelcal refit {} --place '{}'",
                              place_flag, WelcomeInput(inputs, welcome_key::kPlace), when, session, place_flag));
  return out;
}

}  // namespace accelcal
