// `accelcal report`: the calibration report of a session or of a calibration file, as text,
// HTML or JSON; or the session's calibration file itself. What goes into the report (the input
// read, the session's meta, the procedure's limits) is app/report_metadata.h's.
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include "accelcal/app/report_metadata.h"
#include "accelcal/app/fixture/sensor_batch.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/io/report_json.h"
#include "accelcal/report/report_html.h"
#include "accelcal/report/report_model.h"
#include "accelcal/report/report_text.h"
#include "cli/commands.h"
#include "cli/output.h"
#include "cli/shipped_files.h"

namespace accelcal::cli {
namespace {

struct ReportCommandOptions {
  std::string input;             // session path or name, or a calibration file (JSON)
  std::string format = "text";   // text | html | json | calibration
  std::string output_path;       // empty: stdout
  std::string allan_path;        // allan.json (docs/certificate.md, "Reports"); empty: the session's, if any
  std::string noise_path;        // noise.json; empty: the session's, if any
  std::string procedure_path;    // limits from here; empty: the default procedure when it matches
  int sensor = 1;                // --sensor N: which sensor of a several-sensor session (1-based)
};

// `--format batch-csv`: every sensor of the session, one row each (app/sensor_batch.h).
void RunBatchCsv(const ReportCommandOptions& o, const ReportRequest& request) {
  const std::vector<SensorBatchRow> rows = SensorBatchOf(request);
  WriteOutputText(o.output_path, BatchSummaryCsv(rows));
  if (!o.output_path.empty())
    std::cout << fmt::format("batch summary of {} sensor(s) written to {}\n", rows.size(),
                             o.output_path);
}

void RunReport(const ReportCommandOptions& o) {
  if (o.format == "calibration") {
    const Calibration cal = ReportInputsOf(o.input, o.sensor - 1).calibration;
    WriteOutputText(o.output_path, CalibrationToJsonText(cal) + "\n");
    if (!o.output_path.empty()) std::cout << fmt::format("calibration written to {}\n", o.output_path);
    return;
  }
  ReportRequest request;
  request.input = o.input;
  request.procedure_path = o.procedure_path;
  request.default_procedure_path = ShippedProcedurePath("full_calibration.toml");
  request.allan_path = o.allan_path;
  request.noise_path = o.noise_path;
  request.sensor = o.sensor - 1;
  if (o.format == "batch-csv") return RunBatchCsv(o, request);
  const ReportModel model = BuildReportModel(ReportInputsFor(request));
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
      "  accelcal report /tmp/s.db --format calibration -o cal.json\n"
      "  accelcal report plate.db --format batch-csv -o batch.csv\n"
      "  accelcal report plate.db --sensor 3 --format html -o board3.html");
  sub->add_option("input", opts->input,
                  "Session file, a session's name in the default directory, or a calibration file")
      ->required();
  sub->add_option("--format", opts->format,
                  "text, html, json (the report), calibration, or batch-csv (one row per sensor "
                  "of a several-sensor session)")
      ->check(CLI::IsMember({"text", "html", "json", "calibration", "batch-csv"}))
      ->capture_default_str();
  sub->add_option("--sensor", opts->sensor,
                  "Which sensor of a several-sensor session (1-based; every format but batch-csv)")
      ->check(CLI::PositiveNumber)->capture_default_str();
  sub->add_option("-o,--output", opts->output_path, "Write here instead of standard output");
  sub->add_option("--allan", opts->allan_path, "Allan-deviation analysis (JSON) to include");
  sub->add_option("--noise", opts->noise_path, "Noise analysis (JSON) to include");
  sub->add_option("--procedure", opts->procedure_path,
                  "Procedure whose [limits] decide pass/fail (default: the full calibration, when "
                  "the session ran it)")
      ->transform(ShippedFile(kShippedProcedures));
  sub->callback([opts] { RunReport(*opts); });
}

}  // namespace accelcal::cli
