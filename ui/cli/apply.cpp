#include "cli/commands.h"

#include "accelcal/error.h"

namespace accelcal::cli {

void SetupApplyCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("apply", "(not yet written)");
  sub->callback([] { throw Error("'apply' is not implemented yet"); });
}

}  // namespace accelcal::cli
