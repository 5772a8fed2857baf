// `accelcal report`: the calibration report of a session or of a calibration file, as text,
// HTML or JSON; or the session's calibration file itself.
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/app/report_inputs.h"
#include "accelcal/app/wizard/equipment_input.h"
#include "accelcal/io/allan_file.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/io/noise_file.h"
#include "accelcal/io/text_file.h"
#include "accelcal/app/report_files.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/report/report_html.h"
#include "accelcal/io/report_json.h"
#include "accelcal/report/report_model.h"
#include "accelcal/report/report_text.h"
#include "accelcal/session/session_paths.h"
#include "accelcal/session/session_store.h"
#include "cli/commands.h"
#include "cli/output.h"
#include "cli/shipped_files.h"

namespace accelcal::cli {
namespace {

struct ReportCommandOptions {
  std::string input;             // session path or name, or a calibration file (JSON)
  std::string format = "text";   // text | html | json | calibration
  std::string output_path;       // empty: stdout
  std::string allan_path;        // allan.json (README "Reports"); empty: the session's, if any
  std::string noise_path;        // noise.json; empty: the session's, if any
  std::string procedure_path;    // limits from here; empty: the default procedure when it matches
};

// A calibration file is JSON (its first non-blank byte is '{'); a session is SQLite.
bool LooksLikeJson(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char c = 0;
  while (in.get(c))
    if (c != ' ' && c != '\n' && c != '\r' && c != '\t') return c == '{';
  return false;
}

ReportInputs FromSession(const std::string& input) {
  SessionOpenOptions read_only;
  read_only.read_only = true;
  const std::string path = ResolveSessionPath(input);
  const std::unique_ptr<SessionStore> store = SessionStore::Open(path, read_only);
  const SessionInfo info = store->Info();
  const std::optional<std::string> result = store->Result();
  if (!result && !DescribeRecords(*store).empty())
    throw Error(fmt::format("session {} has no calibration: it holds records ({}), which another "
                            "command analyses", path, DescribeRecords(*store)));
  if (!result)
    throw Error(fmt::format("session {} has no calibration yet: {} captures accepted; run the "
                            "wizard to finish it", path, info.num_captures));
  ReportInputs in = ReportInputsFromJournal(*store, path);
  in.meta.device = info.device;
  in.meta.operator_name = info.operator_name;
  in.meta.date_utc = info.updated_utc;
  in.meta.session_name = info.name;
  in.meta.session_path = info.path;
  in.meta.procedure = info.procedure;
  in.meta.source = info.source;
  return in;
}

// The procedure's equipment as the session's welcome edited it (the same list the wizard's
// report showed), and its nominal zero-g level.
void SetEquipment(const Procedure& p, ReportInputs* in) {
  const EquipmentAnswer edited = ApplyEquipmentAnswer(in->equipment_answer, p.equipment);
  in->equipment = edited.ok() ? edited.items : p.equipment;
  in->nominal_bias_counts = p.nominal.bias_counts;
  in->nominal_scale_counts_per_mps2 = p.nominal.scale_counts_per_mps2;
}

void AddLimits(const ReportCommandOptions& o, ReportInputs* in) {
  if (!o.procedure_path.empty()) {
    const Procedure p = LoadProcedure(o.procedure_path);
    in->limits = p.limits;
    SetEquipment(p, in);
    if (in->meta.procedure.empty()) in->meta.procedure = p.title;
    return;
  }
  // The session names its procedure by title: its limits are the default procedure's only when
  // that is the one it ran (a calibration file alone states no procedure).
  if (in->meta.procedure.empty()) return;
  try {
    const Procedure p = LoadProcedure(ShippedProcedurePath("seed_calibration.toml"));
    if (p.title == in->meta.procedure) {
      in->limits = p.limits;
      SetEquipment(p, in);
    }
  } catch (const Error&) {
    // No default procedure installed: the report says no limits were stated.
  }
}

void RunReport(const ReportCommandOptions& o) {
  ReportInputs in;
  if (IsReadOnceInput(o.input) || LooksLikeJson(o.input)) {
    const std::string text = ReadTextFile(o.input);
    in.calibration = CalibrationFromJsonText(text, o.input);
    ReadAnalysesFromResultText(text, o.input, &in);
  } else {
    in = FromSession(o.input);
  }
  if (o.format == "calibration") {
    WriteOutputText(o.output_path, CalibrationToJsonText(in.calibration) + "\n");
    if (!o.output_path.empty()) std::cout << fmt::format("calibration written to {}\n", o.output_path);
    return;
  }
  AddLimits(o, &in);
  if (!o.allan_path.empty()) in.allan = ReadAllanFile(o.allan_path);
  if (!o.noise_path.empty()) in.noise = ReadNoiseFile(o.noise_path);
  const ReportModel model = BuildReportModel(in);
  std::string text;
  if (o.format == "html") text = RenderReportHtml(model);
  else if (o.format == "json") text = ReportJsonText(model);
  else text = RenderReportText(model);
  WriteOutputText(o.output_path, text);
  if (!o.output_path.empty())
    std::cout << fmt::format("{} report written to {} ({})\n", o.format, o.output_path,
                             VerdictToString(model.verdict));
}

}  // namespace

void SetupReportCommand(CLI::App& app) {
  auto opts = std::make_shared<ReportCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "report",
      "The calibration report of a session or of a calibration file: device, operator, date,\n"
      "gravity, procedure, captures, parameters with 1-sigma uncertainties, residuals, the\n"
      "diagnosis before/after, noise and drift, pass/fail against the procedure's limits.\n"
      "As text (80 columns, for paper), one self-contained HTML file with plots, or JSON;\n"
      "--format calibration writes the session's calibration file that `accelcal apply` reads.\n\n"
      "Examples:\n"
      "  accelcal report 20250301T140509Z\n"
      "  accelcal report /tmp/s.db --format html -o report.html --allan allan.json\n"
      "  accelcal report cal.json --format json\n"
      "  accelcal report /tmp/s.db --format calibration -o cal.json");
  sub->add_option("input", opts->input,
                  "Session file, a session's name in the default directory, or a calibration file")
      ->required();
  sub->add_option("--format", opts->format, "text, html, json (the report) or calibration")
      ->check(CLI::IsMember({"text", "html", "json", "calibration"}))->capture_default_str();
  sub->add_option("-o,--output", opts->output_path, "Write here instead of standard output");
  sub->add_option("--allan", opts->allan_path, "Allan-deviation analysis (JSON) to include");
  sub->add_option("--noise", opts->noise_path, "Noise analysis (JSON) to include");
  sub->add_option("--procedure", opts->procedure_path,
                  "Procedure whose [limits] decide pass/fail (default: the seed procedure, when "
                  "the session ran it)")
      ->transform(ShippedFile(kShippedProcedures));
  sub->callback([opts] { RunReport(*opts); });
}

}  // namespace accelcal::cli
