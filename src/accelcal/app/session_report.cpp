#include "accelcal/app/session_report.h"

#include <fmt/core.h>

#include "accelcal/app/report_inputs.h"
#include "accelcal/app/wizard/equipment_input.h"
#include "accelcal/base/error.h"
#include "accelcal/io/procedure_file.h"

namespace accelcal {

ReportInputs ReportInputsOfSession(const SessionStore& store, const std::string& default_procedure_path) {
  const SessionInfo info = store.Info();
  const std::optional<std::string> result = store.Result();
  if (!result && !DescribeRecords(store).empty())
    throw Error(
        fmt::format("session {} has no calibration: it holds records ({}), which another "
                    "command analyses",
                    info.path, DescribeRecords(store)));
  if (!result)
    throw Error(
        fmt::format("session {} has no calibration yet: {} captures accepted; run the "
                    "wizard to finish it",
                    info.path, info.num_captures));
  ReportInputs in = ReportInputsFromJournal(store, info.path);
  in.meta.device = info.device;
  in.meta.operator_name = info.operator_name;
  in.meta.date_utc = info.updated_utc;
  in.meta.session_name = info.name;
  in.meta.session_path = info.path;
  in.meta.procedure = info.procedure;
  in.meta.source = info.source;
  // One sensor per session today: its lab number, once published.
  for (const LabCertificateMark& mark : store.LabCertificates())
    if (mark.sensor_index == 0) in.meta.certificate_number = mark.certificate_number;
  // The session names its procedure by title: its limits are the default procedure's only when
  // that is the one it ran.
  if (!in.meta.procedure.empty()) {
    try {
      const Procedure p = LoadProcedure(default_procedure_path);
      if (p.title == in.meta.procedure) ApplyProcedureToReport(p, &in);
    } catch (const Error&) {
      // No default procedure installed: the report says no limits were stated.
    }
  }
  return in;
}

void ApplyProcedureToReport(const Procedure& p, ReportInputs* in) {
  in->limits = p.limits;
  // The procedure's equipment as the session's welcome edited it (the list the wizard's report
  // showed).
  const EquipmentAnswer edited = ApplyEquipmentAnswer(in->equipment_answer, p.equipment);
  in->equipment = edited.ok() ? edited.items : p.equipment;
  in->nominal_bias_counts = p.nominal.bias_counts;
  if (in->meta.procedure.empty()) in->meta.procedure = p.title;
}

}  // namespace accelcal
