#include "cli/cli_checks.h"
#include "cli/wizard.h"

#include <cstdlib>
#include <functional>
#include <iostream>
#include <memory>
#include <vector>

#include <unistd.h>

#include <fmt/core.h>

#include "accelcal/app/lab_equipment_check.h"
#include "accelcal/app/lab_publish.h"
#include "accelcal/base/error.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/io/scenario_file.h"
#include "accelcal/session/session_paths.h"
#include "accelcal/acquire/mavlink/mavlink_source.h"
#include "accelcal/acquire/source/remote_bench.h"
#include "accelcal/acquire/source/source_spec.h"
#include "accelcal/session/procedure.h"
#include "accelcal/app/refit_session.h"
#include "accelcal/app/wizard/virtual_lab.h"
#include "accelcal/app/wizard/wizard_engine.h"
#include "cli/commands.h"
#include "cli/output.h"
#include "cli/source_preflight.h"
#include "cli/terminal_answers.h"
#include "cli/usage_errors.h"
#include "cli/gravity_options.h"
#include "cli/wizard_fixture.h"
#include "accelcal/app/fixture/fixture_driver.h"
#include "cli/wizard_journal.h"
#include "cli/shipped_files.h"
#include "frontend.h"

namespace accelcal::cli {
namespace {

// The operator offered at the welcome: the login name; on the virtual bench, where nobody may
// be logged in (a CI runner), a stand-in so that `yes ''` still answers a procedure that
// requires an operator. A real bench offers nothing when no one is logged in.
std::string DefaultOperator(bool sim) {
  for (const char* name : {"USER", "LOGNAME"})
    if (const char* user = std::getenv(name); user != nullptr && *user != '\0') return user;
  return sim ? "sim operator" : "";
}

// The wizard's end on a bench pointed at a lab (docs/lab.md): the finished session published to
// the lab's register, its number written back; a lab out of reach leaves it in the backlog.
void PublishAtTheEnd(const std::string& session, const std::string& procedure_path) {
  if (!LabConfigured()) return;
  std::cout << fmt::format("Sending the session to the lab's register (waiting at most {} s for it)...",
                           kLabQuickConnectTimeoutS)
            << std::endl;
  SessionOpenOptions existing;
  existing.create_if_missing = false;
  const std::unique_ptr<SessionStore> store = SessionStore::Open(session, existing);
  if (const std::optional<SessionPublishOutcome> outcome = PublishIfLabConfigured(*store, procedure_path))
    std::cout << "The lab's register: " << DescribeOutcome(*outcome) << "\n";
}

// WelcomeEquipmentCheck, saying on the terminal what the wizard waits for before the first
// check: it runs while the engine is built, before the welcome is on the screen (the TUI's too),
// and a lab that does not answer holds it up to kLabQuickConnectTimeoutS.
std::function<WelcomeLabCheck(const std::vector<EquipmentItem>&)> AnnouncedEquipmentCheck() {
  return [check = WelcomeEquipmentCheck(), first = true](const std::vector<EquipmentItem>& items) mutable {
    if (first && LabConfigured())
      std::cout << fmt::format("Checking the bench's equipment with the lab's register (waiting at most {} s "
                               "for it)...",
                               kLabQuickConnectTimeoutS)
                << std::endl;
    first = false;
    return check(items);
  };
}

}  // namespace

int RunWizard(const WizardCommandOptions& options) {
  RefuseAbsentSerialPort(options.source);  // before the session file is created
  const std::string procedure_path =
      options.procedure_path.empty() ? ShippedProcedurePath("full_calibration.toml") : options.procedure_path;
  Procedure procedure = LoadProcedure(procedure_path);
  // `--source -`: stdin carries the samples, so the answers come from the terminal (refused
  // here, before anything is opened or written, when there is none).
  std::unique_ptr<TerminalAnswers> tty;
  if (options.source == "-") tty = std::make_unique<TerminalAnswers>();
  SourceOptions source_options;
  source_options.sim.speed = options.speed;
  source_options.seed = options.seed;
  const bool sim = options.source == "sim";
  if (!options.scenario_path.empty()) source_options.scenario = sim::LoadScenario(options.scenario_path);
  // Several sensors at once (cli/wizard_fixture.h): asked for, or the scenario's plate.
  const bool several = WantsFixture(options) || (source_options.scenario && source_options.scenario->fixture);
  std::unique_ptr<SampleSource> source;
  std::unique_ptr<SensorSetSource> set;
  if (several) set = OpenWizardSensorSet(options, source_options);
  if (set) {
    if (const std::string why = FixtureTurntableProblem(set->fixture(), procedure); !why.empty())
      throw Error("the fixture cannot run this procedure's turntable steps: " + why);
  }
  else source = OpenSource(options.source, source_options);
  // The vehicle's calibration (each of its IMUs') is said at the welcome (and recorded there); a
  // refusal, here.
  std::vector<std::string> device_lines;
  if (source) device_lines = PrepareVehicle(*source, options.vehicle_calibration, nullptr, stdout);
  if (set) device_lines = PrepareVehicle(*set, options.vehicle_calibration, nullptr, stdout);
  // The vehicle, for the write-back step, before the source is wrapped.
  MavlinkSource* vehicle = dynamic_cast<MavlinkSource*>(source.get());
  if (source && !options.bench_control.empty())
    source = WithRemoteBench(std::move(source), ParseHostPort(options.bench_control, options.bench_control,
                                                              "--bench-control HOST:PORT"));
  // A new session goes to the default session directory, where `accelcal sessions` looks.
  const std::string session = options.session_path.empty() ? NewSessionPath() : options.session_path;
  std::unique_ptr<SessionJournal> journal = OpenWizardJournal(session, procedure.title, options.source);
  FixtureWizard fixture;
  if (several) {
    // Line mode says each sensor after each pose, a line each (taken: still, in its pose; or
    // left out: why); the TUI shows them live (WizardView::sensors).
    const bool line_mode = tty || options.plain || ::isatty(STDOUT_FILENO) != 1;
    fixture = OpenFixtureWizard(std::move(set), options, procedure, *journal,
                                [line_mode](const std::string& note) {
                                  if (line_mode) std::cout << "  " << note << "\n";
                                });
  }
  SampleSource& samples = several ? *fixture.source : *source;
  SessionJournal& record = several ? static_cast<SessionJournal&>(*fixture.journal) : *journal;

  WizardOptions wizard;
  wizard.session_name = session;
  wizard.default_operator = DefaultOperator(sim);
  wizard.default_device = several ? "fixture" : sim ? "SIM-0001" : "";
  wizard.default_place = options.place;
  wizard.fixed_duration_s = options.fixed_duration_s;
  wizard.device_lines = std::move(device_lines);
  wizard.vehicle = vehicle;
  if (fixture.vehicle != nullptr)
    wizard.write_back_elsewhere =
        "This session calibrates each of the vehicle's IMUs: each is written into the vehicle on its own "
        "once all are calibrated; the session's last lines name the command for each IMU.";
  wizard.gravity = options.gravity;
  // The virtual bench's lab: its gravity and its identified, verified equipment (virtual_lab.h).
  if (sim)
    OfferVirtualLab(source_options.scenario ? *source_options.scenario : sim::DefaultScenario(),
                    !options.gravity_flag.empty(), &wizard);
  wizard.report_beside = session;
  if (!options.no_lab) wizard.check_equipment = AnnouncedEquipmentCheck();
  // A flag this run does not use (the session recorded its own at its welcome) is said, never
  // silently ignored.
  wizard.notes = UnusedResumeFlags(record, session, options.gravity_flag, options.place);
  WizardEngine engine(procedure, samples, record, wizard);
  // On a fixture, a sensor left out of a pose is asked about on top of the engine's screens.
  std::unique_ptr<FixtureWizardDriver> fixture_driver;
  if (several) fixture_driver = std::make_unique<FixtureWizardDriver>(engine, *fixture.journal, *fixture.source);
  WizardDriver& driver = several ? static_cast<WizardDriver&>(*fixture_driver) : engine;

  const bool terminal = ::isatty(STDIN_FILENO) == 1 && ::isatty(STDOUT_FILENO) == 1;
  int status = 0;
  if (tty) {
    status = ui::RunLineModeOn(driver, tty->fd(), true, std::cout);  // stdin is the samples'
  } else if (terminal && !options.plain) {
    status = ui::RunTui(driver);
  } else {
    // On a terminal, q is read while the wizard captures; a pipe's lines wait for questions.
    status = ui::RunLineModeOn(driver, STDIN_FILENO, ::isatty(STDIN_FILENO) == 1, std::cout);
  }
  // A session left at a dead end (a fit refused, a capture refused again and again) is saved
  // to resume like one left with q, but the job failed: a script must not take it for done.
  if (status == 0 && engine.left_on_failure()) return kExitFailure;
  // Done only when the procedure ran to its end; a session left with q stays open to resume.
  if (status == 0 && engine.completed() && several)
    FinishFixtureWizard(fixture, *journal, procedure, procedure_path, session, std::cout);
  if (status == 0 && engine.completed()) {
    journal->MarkDone();
    fixture_driver.reset();
    fixture = {};     // holds the session: let go first
    journal.reset();  // closed before the session is opened to publish it
    if (!options.no_lab) PublishAtTheEnd(session, procedure_path);
  }
  return status;
}

void SetupWizardCommand(CLI::App& app) {
  auto options = std::make_shared<WizardCommandOptions>();
  auto gravity = std::make_shared<GravityFlags>();
  CLI::App* sub = app.add_subcommand(
      "wizard",
      "Guided calibration at the bench: level the table, the prism poses, the turntable runs,\n"
      "the fit, the diagnosis and the report, recorded in a session as it goes (an interrupted\n"
      "session resumes). Runs on the virtual bench unless --source names a real one. Also what\n"
      "`accelcal` with no arguments does.");
  sub->add_option("--source", options->source, "Sample source: sim, file:PATH, serial:DEV@BAUD, "
                  "tcp:HOST:PORT, mavlink:LINK[,imu=N,rate=HZ], iio:DEVICE[,...] or - (default sim)");
  sub->add_option("--speed", options->speed,
                  "sim: simulated seconds per wall-clock second (default 1; 0 = as fast as possible)")
      ->check(NonNegative());
  sub->add_option("--seed", options->seed, "sim: random seed, overriding the scenario's");
  sub->add_option("--scenario", options->scenario_path,
                  "sim: virtual-bench scenario (TOML), or a shipped one's name (clumsy_bump); default: "
                  "the built-in default bench")
      ->transform(ShippedFile(kShippedScenarios));
  sub->add_option("--procedure", options->procedure_path,
                  "Procedure file (TOML), or a shipped one's name (noise.toml); default: the shipped "
                  "full_calibration.toml")
      ->transform(ShippedFile(kShippedProcedures));
  sub->add_option("--place", options->place, "The lab or bench, offered at the welcome (for the report)");
  sub->add_option("--session", options->session_path,
                  "Session file: created when new, resumed when it exists (default: a new one)");
  sub->add_flag("--plain", options->plain, "Plain line mode even on a terminal");
  sub->add_option("--fixed-duration", options->fixed_duration_s,
                  "Every capture this long, s, as before the plan (for comparison); default: the "
                  "procedure's [target] plans each capture's length")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--no-lab", options->no_lab,
                "On a bench pointed at a lab's register (docs/lab.md): neither check the equipment\n"
                "at the welcome nor publish the finished session (`accelcal lab publish` does later)");
  sub->add_option("--vehicle-calibration", options->vehicle_calibration,
                  "mavlink: the vehicle's own accelerometer calibration: undo (take it out of every "
                  "sample: the nine parameters describe the sensor) or as-is")
      ->check(CLI::IsMember({"undo", "as-is"}))->capture_default_str();
  sub->add_option("--bench-control", options->bench_control,
                  "The virtual bench behind --source is another process's (accelcal record "
                  "--bench-listen): its controls at HOST:PORT place the sensor (tests)");
  sub->add_option("--sensors", options->sensors,
                  "sim: a plate of N boards calibrated at once, each on its own (docs/fixtures.md)")
      ->check(CLI::Range(1, 64));
  sub->add_option("--fixture", options->fixture_path,
                  "Several sensors at once: the fixture file (serials, mountings, offsets; "
                  "docs/fixtures.md)");
  sub->add_option("--columns", options->columns,
                  "A text source carrying several sensors: its columns, one ax,ay,az triple per "
                  "sensor (t,ax,ay,az,ax,ay,az,...)");
  gravity->Bind(*sub);
  sub->footer(
      "Examples:\n"
      "  accelcal wizard                                   # the virtual bench, full screen\n"
      "  accelcal wizard --source serial:/dev/ttyUSB0@115200 --session bench.db\n"
      "  yes '' | accelcal wizard --source sim --speed 50 --session /tmp/s.db --plain\n"
      "The welcome asks the local gravity (the gravity flags give its default answer; else\n"
      "'standard', said explicitly).");
  sub->callback([options, gravity] {
    options->gravity = gravity->Resolve();
    options->gravity_flag = gravity->Given();
    if (RunWizard(*options) != 0) throw Error("the wizard stopped on a failure");
  });
}

}  // namespace accelcal::cli
