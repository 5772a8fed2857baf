#include "cli/commands.h"

#include "accelcal/error.h"

namespace accelcal::cli {

void SetupSimulateCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("simulate", "(not yet written)");
  sub->callback([] { throw Error("'simulate' is not implemented yet"); });
}

}  // namespace accelcal::cli
