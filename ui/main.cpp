// accelcal: calibrate a three-axis accelerometer (see README.md).
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/base/version.h"
#include "accelcal/base/error.h"
#include "accelcal/base/safe_text.h"
#include "cli/cli_checks.h"
#include "cli/commands.h"
#include "cli/usage_errors.h"
#include "cli/wizard.h"
#include "git_description.h"

namespace {

// "0.1.0 (git 68dabc6)": the release and, when built from a checkout, the commit.
std::string VersionText() {
  std::string version = accelcal::kAccelcalVersion;
  if (*accelcal::kGitDescription != '\0') version += std::string(" (git ") + accelcal::kGitDescription + ")";
  return version;
}

}  // namespace

int main(int argc, char** argv) {
  // The step kinds defined beside their wizard controllers, before any procedure is read.
  accelcal::RegisterStepKinds();
  CLI::App app{
      "accelcal: calibrate the three-axis accelerometer of an IMU (the nine-parameter model of\n"
      "scale K, bias b and misalignment T) from static poses and turntable runs.\n\n"
      "With no subcommand: the guided wizard on the virtual bench, in a new session.\n\n"
      "Example:\n"
      "  accelcal wizard --source serial:/dev/ttyUSB0@115200 --session bench.db\n"
      "  accelcal simulate bench_default -o captures.csv\n"
      "  accelcal fit captures.csv -o cal.json\n"
      "  accelcal apply cal.json < raw.txt > calibrated.txt",
      "accelcal"};
  app.footer(
      "Each command's options: accelcal COMMAND --help, or man accelcal-COMMAND.\n"
      "Files:\n"
      "  The procedures and virtual-bench scenarios shipped with accelcal are in share/accelcal/\n"
      "  beside the program (/usr/share/accelcal/procedures, .../scenarios); one is named by its\n"
      "  file name alone (--procedure noise.toml, --scenario clumsy_bump). Sessions go to\n"
      "  $XDG_DATA_HOME/accelcal/sessions (~/.local/share/accelcal/sessions).\n"
      "Exit status:\n"
      "  0 done (also --help and --version); 1 the job failed or its input was refused (a file\n"
      "  missing or unreadable, a refused value, a source that is not there); 2 the command line\n"
      "  is wrong.");
  app.set_version_flag("--version", "accelcal " + VersionText());
  app.require_subcommand(0, 1);
  accelcal::cli::SetupFitCommand(app);
  accelcal::cli::SetupApplyCommand(app);
  accelcal::cli::SetupSimulateCommand(app);
  accelcal::cli::SetupRecordCommand(app);
  accelcal::cli::SetupSessionsCommand(app);
  accelcal::cli::SetupExportCommand(app);
  accelcal::cli::SetupExportCalCommand(app);
  accelcal::cli::SetupHistoryCommand(app);
  accelcal::cli::SetupReportCommand(app);
  accelcal::cli::SetupRefitCommand(app);
  accelcal::cli::SetupWizardCommand(app);
  accelcal::cli::SetupAllanCommand(app);
  accelcal::cli::SetupNoiseCommand(app);
  accelcal::cli::SetupLabCommand(app);
  accelcal::cli::SetupDeviceInfoCommand(app);
  accelcal::cli::SetupBagInfoCommand(app);
  accelcal::cli::SetupHelpCommands(app, "accelcal " + VersionText());  // last: it walks the others
  accelcal::cli::RefuseNegativeWholeNumbers(app);

  try {
    app.parse(argc, argv);
    // No subcommand: the wizard on the virtual bench with its defaults, in a new session.
    if (app.get_subcommands().empty()) return accelcal::cli::RunWizard({});
  } catch (const CLI::ParseError& e) {
    // Help and version (exit 0); a command line that is wrong (exit 2, with "did you mean").
    return accelcal::cli::ReportParseError(app, e, std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::exception& e) {
    std::fflush(stdout);
    // A message may quote a file's field or a typed answer: no control character reaches the
    // terminal as it is.
    fmt::print(stderr, "accelcal: error: {}\n", accelcal::DisplayLines(e.what()));
    return accelcal::cli::kExitFailure;
  }
  return 0;
}
