#include "accelcal/app/report_metadata.h"

#include "accelcal/app/calibration_input.h"
#include "accelcal/app/report_inputs.h"
#include "accelcal/app/wizard/equipment_input.h"
#include "accelcal/base/error.h"
#include "accelcal/io/allan_file.h"
#include "accelcal/io/noise_file.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/io/session_result_file.h"
#include "accelcal/session/sensor_journal_view.h"

namespace accelcal {

namespace {

ReportInputs FromSession(const std::string& path, int sensor) {
  const SessionWithResult session = OpenSessionResult(path, sensor);
  // A sensor of a several-sensor session reads as a one-sensor session (its captures, result).
  SensorJournalView view(*session.store, sensor);
  ReportInputs in = ReportInputsFromJournal(view, path);
  const SessionInfo& info = session.info;
  in.meta.device = info.device;
  in.meta.operator_name = info.operator_name;
  in.meta.date_utc = info.updated_utc;
  in.meta.session_name = info.name;
  in.meta.session_path = info.path;
  in.meta.procedure = info.procedure;
  in.meta.source = info.source;
  // The sensor's lab number, once published (docs/lab.md; keyed by sensor index).
  for (const LabCertificateMark& mark : session.store->LabCertificates())
    if (mark.sensor_index == sensor) in.meta.certificate_number = mark.certificate_number;
  return in;
}

// The procedure's equipment as the session's welcome edited it (the same list the wizard's
// report showed), and its nominal zero-g level and scale.
void SetEquipment(const Procedure& p, ReportInputs* in) {
  const EquipmentAnswer edited = ApplyEquipmentAnswer(in->equipment_answer, p.equipment);
  in->equipment = edited.ok() ? edited.items : p.equipment;
  in->nominal_bias_counts = p.nominal.bias_counts;
  in->nominal_scale_counts_per_mps2 = p.nominal.scale_counts_per_mps2;
}

void AddLimits(const ReportRequest& r, ReportInputs* in) {
  if (!r.procedure_path.empty()) {
    const Procedure p = LoadProcedure(r.procedure_path);
    in->limits = p.limits;
    SetEquipment(p, in);
    if (in->meta.procedure.empty()) in->meta.procedure = p.title;
    return;
  }
  // The session names its procedure by title: its limits are the default procedure's only when
  // that is the one it ran, under its title or a former one (a calibration file alone states no
  // procedure).
  if (in->meta.procedure.empty() || r.default_procedure_path.empty()) return;
  try {
    const Procedure p = LoadProcedure(r.default_procedure_path);
    if (p.IsTitled(in->meta.procedure)) {
      in->limits = p.limits;
      SetEquipment(p, in);
    }
  } catch (const Error&) {
    // No default procedure installed: the report says no limits were stated.
  }
}

}  // namespace

ReportInputs ReportInputsOf(const std::string& input, int sensor) {
  const LocatedCalibrationInput at = LocateCalibrationInput(input);
  if (at.kind == CalibrationInputKind::kSession) return FromSession(at.path, sensor);
  const CalibrationInput file = ReadCalibrationInput(at, sensor);
  ReportInputs in;
  in.calibration = file.calibration;
  ReadAnalysesFromResultText(file.text, file.path, &in);
  return in;
}

ReportInputs ReportInputsFor(const ReportRequest& request) {
  ReportInputs in = ReportInputsOf(request.input, request.sensor);
  AddLimits(request, &in);
  if (!request.allan_path.empty()) in.allan = ReadAllanFile(request.allan_path);
  if (!request.noise_path.empty()) in.noise = ReadNoiseFile(request.noise_path);
  return in;
}

}  // namespace accelcal
