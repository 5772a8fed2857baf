// `accelcal refit SESSION`: a finished session fitted again with corrected inputs (gravity,
// equipment, identification); the use case is app/refit_session.h's RefitSessionFile (the
// session opened by app/calibration_input.h's rule), this is its command line.
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include "accelcal/app/refit_session.h"
#include "cli/commands.h"
#include "cli/gravity_options.h"
#include "cli/output.h"
#include "cli/shipped_files.h"

namespace accelcal::cli {
namespace {

struct RefitCommandOptions {
  std::string session;         // path or name
  std::string procedure_path;  // empty: the shipped full procedure, when the session ran it
  std::optional<std::string> equipment, device, operator_name, place;
};

void RunRefit(const RefitCommandOptions& o, const GravityFlags& gravity) {
  RefitFileRequest request;
  request.input = o.session;
  request.procedure_path = o.procedure_path;
  request.default_procedure_path = ShippedProcedurePath("full_calibration.toml");
  if (!gravity.Given().empty()) request.corrections.gravity = gravity.Resolve();
  request.corrections.equipment_answer = o.equipment;
  request.corrections.device = o.device;
  request.corrections.operator_name = o.operator_name;
  request.corrections.place = o.place;
  const RefitFileOutcome done = RefitSessionFile(request);
  const RefitOutcome& out = done.refit;
  std::cout << fmt::format("Refitted session {} ({}):\n", done.path, out.refit_step);
  if (out.changes.empty()) std::cout << "  no input changed: fitted again as recorded\n";
  for (const std::string& c : out.changes) std::cout << "  " << c << '\n';
  for (const std::string& line : out.summary.lines) std::cout << "  " << line << '\n';
  std::cout << fmt::format("The earlier calibration{} kept in the session ({} in all); `accelcal report {}` "
                           "shows this one and lists what changed.\n",
                           out.earlier_results == 1 ? " is" : "s are", out.earlier_results + 1, o.session);
}

}  // namespace

void SetupRefitCommand(CLI::App& app) {
  auto opts = std::make_shared<RefitCommandOptions>();
  auto gravity = std::make_shared<GravityFlags>();
  CLI::App* sub = app.add_subcommand(
      "refit",
      "Fit a finished session again with corrected inputs: the local gravity, the bench's\n"
      "equipment, the identification. The new calibration becomes the session's result, the\n"
      "earlier ones stay in the session (never replaced silently), and the report beside the\n"
      "session is written again.\n\n"
      "Examples:\n"
      "  accelcal refit 20250301T140509Z --gravity 9.7803+-0.00001\n"
      "  accelcal refit /tmp/s.db --latitude -34.9 --altitude 43\n"
      "  accelcal refit /tmp/s.db --equipment 'ruler id RUL-07 u 0.05 cal C-2291' --device SN-42");
  sub->add_option("session", opts->session, "Session file, or a session's name in the default directory")
      ->required();
  gravity->Bind(*sub);
  sub->add_option("--equipment", opts->equipment,
                  "The bench's equipment as the welcome takes it: 'ruler id RUL-07 u 0.05 cal C-2291; "
                  "turntable u 0.03 cal T-118' (u in mm, %, deg), applied over the session's");
  sub->add_option("--device", opts->device, "The device's serial number");
  sub->add_option("--operator", opts->operator_name, "The operator");
  sub->add_option("--place", opts->place, "The lab or bench");
  sub->add_option("--procedure", opts->procedure_path,
                  "The procedure file the session ran, or a shipped one's name (default: the seed "
                  "procedure, when it is the one)")
      ->transform(ShippedFile(kShippedProcedures));
  sub->callback([opts, gravity] { RunRefit(*opts, *gravity); });
}

}  // namespace accelcal::cli
