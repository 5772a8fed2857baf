#include "cli/commands.h"

#include "accelcal/error.h"

namespace accelcal::cli {

void SetupFitCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("fit", "(not yet written)");
  sub->callback([] { throw Error("'fit' is not implemented yet"); });
}

}  // namespace accelcal::cli
