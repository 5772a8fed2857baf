// `accelcal export`: a session's accepted captures as a capture-set file (CSV), which
// `accelcal fit` reads.
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/io/capture_set_writer.h"
#include "accelcal/session/sensor_journal_view.h"
#include "accelcal/session/session_paths.h"
#include "accelcal/session/session_store.h"
#include "cli/commands.h"

namespace accelcal::cli {
namespace {

struct ExportCommandOptions {
  std::string session;      // path or name in the default directory
  std::string output_path;
  int sensor = 1;           // --sensor N of a several-sensor session (1-based)
};

void RunExport(const ExportCommandOptions& o) {
  SessionOpenOptions read_only;
  read_only.read_only = true;
  const std::string path = ResolveSessionPath(o.session);
  const std::unique_ptr<SessionStore> session = SessionStore::Open(path, read_only);
  // One sensor of a several-sensor session reads as a session of its own (its captures).
  const std::unique_ptr<SensorJournalView> store =
      std::make_unique<SensorJournalView>(*session, o.sensor - 1);
  CaptureSet set;
  set.source_name = path;
  // A capture taken again (redo) is superseded: kept in the session, never exported.
  const std::vector<JournalCapture> all = store->Captures();
  const size_t superseded = all.size() - CurrentCaptures(all).size();
  for (JournalCapture& c : CurrentCaptures(all)) set.captures.push_back(std::move(c.capture));
  if (set.captures.empty() && !DescribeRecords(*store).empty())
    throw Error(fmt::format("session {} has no accepted captures: it holds records ({}), which are "
                            "not capture sets", path, DescribeRecords(*store)));
  if (set.captures.empty() && !store->DamagedCaptures().empty())
    throw Error(fmt::format("session {}: nothing to export: {}", path,
                            store->DamagedCaptures().front().Describe()));
  if (set.captures.empty()) throw Error(fmt::format("session {} has no accepted captures yet", path));
  // A capture damaged in the file is never written: it is left out, and said so.
  const std::vector<DamagedCapture> damaged = store->DamagedCaptures();
  WriteCaptureSetFile(o.output_path, set);
  std::cout << fmt::format("{} captures of session {} written to {}\n", set.captures.size(), path,
                           o.output_path);
  for (const DamagedCapture& d : damaged) std::cerr << "not written: " << d.Describe() << "\n";
  if (superseded > 0)
    std::cerr << fmt::format("not written: {} capture{} taken again (superseded by the redo)\n",
                             superseded, superseded == 1 ? "" : "s");
}

}  // namespace

void SetupExportCommand(CLI::App& app) {
  auto opts = std::make_shared<ExportCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "export",
      "Write a session's accepted captures (every sample, with up_axis) as a capture-set file\n"
      "(CSV, format in docs/formats.md) that `accelcal fit` reads. Works while a wizard is running.\n\n"
      "Examples:\n"
      "  accelcal export 20250301T140509Z -o captures.csv\n"
      "  accelcal export /tmp/s.db -o captures.csv && accelcal fit captures.csv");
  sub->add_option("session", opts->session, "Session file, or a session's name in the default directory")
      ->required();
  sub->add_option("-o,--output", opts->output_path, "Capture-set file to write")->required();
  sub->add_option("--sensor", opts->sensor, "Which sensor of a several-sensor session (1-based)")
      ->check(CLI::PositiveNumber)->capture_default_str();
  sub->callback([opts] { RunExport(*opts); });
}

}  // namespace accelcal::cli
