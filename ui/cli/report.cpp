// `accelcal report`: a session's calibration, as text or as the calibration file.
#include <fstream>
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include "accelcal/error.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/report/calibration_text.h"
#include "accelcal/session/session_paths.h"
#include "accelcal/session/session_store.h"
#include "cli/commands.h"

namespace accelcal::cli {
namespace {

struct ReportCommandOptions {
  std::string session;           // path or name in the default directory
  std::string format = "text";   // text | json
  std::string output_path;       // empty: stdout
};

std::string SessionHeader(const SessionInfo& info) {
  return fmt::format("session {} ({})\ncreated {}, updated {}, {}\nprocedure {}, source {}, device "
                     "{}, operator {}\n{} captures accepted\n",
                     info.name, info.path, info.created_utc, info.updated_utc,
                     SessionStateToString(info.state), info.procedure.empty() ? "-" : info.procedure,
                     info.source.empty() ? "-" : info.source, info.device.empty() ? "-" : info.device,
                     info.operator_name.empty() ? "-" : info.operator_name, info.num_captures);
}

void WriteText(const std::string& path, const std::string& text) {
  if (path.empty()) {
    std::cout << text;
    return;
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw Error(fmt::format("cannot write {}", path));
}

void RunReport(const ReportCommandOptions& o) {
  SessionOpenOptions read_only;
  read_only.read_only = true;
  const std::string path = ResolveSessionPath(o.session);
  const std::unique_ptr<SessionStore> store = SessionStore::Open(path, read_only);
  const SessionInfo info = store->Info();
  const std::optional<nlohmann::json> result = store->Result();
  if (!result && !DescribeRecords(*store).empty())
    throw Error(fmt::format("session {} has no calibration: it holds records ({}), which another "
                            "command analyses", path, DescribeRecords(*store)));
  if (!result)
    throw Error(fmt::format("session {} has no calibration yet: {} captures accepted; run the "
                            "wizard to finish it", path, info.num_captures));
  // Checked strictly even for json, so a damaged result is never handed on as good.
  const Calibration cal = CalibrationFromJson(*result, path);
  if (o.format == "json") {
    WriteText(o.output_path, result->dump(2) + "\n");
    if (!o.output_path.empty()) std::cout << fmt::format("calibration written to {}\n", o.output_path);
    return;
  }
  WriteText(o.output_path, SessionHeader(info) + FormatCalibrationText(cal));
}

}  // namespace

void SetupReportCommand(CLI::App& app) {
  auto opts = std::make_shared<ReportCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "report",
      "Print a session's calibration as text (parameters with 1-sigma uncertainties, residuals,\n"
      "every capture), or write it as the calibration file (JSON) that `accelcal apply` reads.\n\n"
      "Examples:\n"
      "  accelcal report 20250301T140509Z\n"
      "  accelcal report /tmp/s.db --format json -o cal.json");
  sub->add_option("session", opts->session, "Session file, or a session's name in the default directory")
      ->required();
  sub->add_option("--format", opts->format, "text or json (the calibration file)")
      ->check(CLI::IsMember({"text", "json"}))->capture_default_str();
  sub->add_option("-o,--output", opts->output_path, "Write here instead of standard output");
  sub->callback([opts] { RunReport(*opts); });
}

}  // namespace accelcal::cli
