// `accelcal lab`: the lab's store, a PostgreSQL database every bench of a lab publishes to
// (docs/lab.md). The connection is libpq's own settings (PG* variables, the service file,
// ~/.pgpass): no option here takes a password.
#include <iostream>
#include <memory>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "accelcal/base/duration_text.h"
#include "accelcal/base/error.h"
#include "accelcal/lab/lab_store.h"
#include "cli/commands.h"
#include "cli/lab_commands.h"
#include "cli/output.h"

namespace accelcal::cli {

namespace {

void RunStatus() {
  const std::unique_ptr<LabStore> lab = LabStore::Connect(true);
  const LabSchemaState state = lab->SchemaState();
  const std::vector<std::string> roles = lab->LabRoles();
  std::cout << fmt::format(
      "{}\nrole {}: {}\nregister version {} (this accelcal: {}){}\n", lab->Identity(), lab->Role(),
      roles.empty() ? "neither a bench nor a lab manager" : fmt::format("{}", fmt::join(roles, ", ")),
      state.version, kLabSchemaVersion, state.usable ? "" : "\n" + state.problem);
}

void RunMigrate(int target) {
  const std::unique_ptr<LabStore> lab = LabStore::Connect(true);
  const int before = lab->SchemaState().version;
  const std::vector<int> applied = lab->Migrate(target);
  if (applied.empty()) {
    std::cout << fmt::format("the register is at version {}: nothing to do\n", before);
    return;
  }
  for (int v : applied)
    std::cout << fmt::format("version {}: {}\n", v, LabMigrations()[static_cast<size_t>(v - 1)].description);
  std::cout << fmt::format("the register is at version {} ({})\n", applied.back(), lab->Identity());
}

void RunStatusChange(const std::vector<std::string>& numbers, LabCertificateStatus status,
                     const std::string& reason) {
  const std::unique_ptr<LabStore> lab = LabStore::Connect();
  for (const std::string& number : numbers) {
    lab->SetCertificateStatus(number, status, reason);
    std::cout << fmt::format("certificate {} {} by {}\n", number, LabCertificateStatusText(status),
                             lab->Role());
  }
}

struct CertificateOptions {
  std::string number;
  std::string format = "html";
  std::string output_path;
};

void RunCertificate(const CertificateOptions& o) {
  const std::unique_ptr<LabStore> lab = LabStore::Connect();
  const std::string media_type = o.format == "html" ? "text/html" : "text/plain";
  for (const LabDocument& d : lab->CertificateDocuments(o.number))
    if (d.media_type == media_type) {
      WriteOutputText(o.output_path, d.bytes);
      return;
    }
  throw Error(fmt::format("the lab holds no {} document of certificate {}", o.format, o.number));
}

long DaysOption(const std::string& text, const char* option) {
  const std::optional<long> days = ParseDays(text);
  if (!days || *days <= 0)
    throw Error(fmt::format("{} {}: give a number of days, weeks or years (365d, 52w, 1y)", option, text));
  return *days;
}

void SetupAdministration(CLI::App& lab) {
  lab.add_subcommand("status",
                     "Which lab store this bench reaches, as which role, and its register's version")
      ->callback([] { RunStatus(); });

  auto target = std::make_shared<int>(kLabSchemaVersion);
  CLI::App* migrate = lab.add_subcommand(
      "migrate",
      "Create the lab's register, or bring it to this accelcal's version (the database's owner;\n"
      "the first time also CREATEROLE, for the groups accelcal_bench and accelcal_manager)");
  migrate->add_option("--to", *target, "Register version to reach (default: this accelcal's)")
      ->capture_default_str();
  migrate->callback([target] { RunMigrate(*target); });

  auto numbers = std::make_shared<std::vector<std::string>>();
  CLI::App* approve = lab.add_subcommand("approve", "A lab manager signs certificates (status approved)");
  approve->add_option("certificate", *numbers, "Certificate numbers")->required();
  approve->callback([numbers] { RunStatusChange(*numbers, LabCertificateStatus::kApproved, ""); });

  auto withdrawn = std::make_shared<std::vector<std::string>>();
  auto reason = std::make_shared<std::string>();
  CLI::App* withdraw = lab.add_subcommand(
      "withdraw", "A lab manager withdraws certificates (they stay in the register, marked withdrawn)");
  withdraw->add_option("certificate", *withdrawn, "Certificate numbers")->required();
  withdraw->add_option("--reason", *reason, "Why (kept with the certificate)")->required();
  withdraw->callback(
      [withdrawn, reason] { RunStatusChange(*withdrawn, LabCertificateStatus::kWithdrawn, *reason); });

  auto cert = std::make_shared<CertificateOptions>();
  CLI::App* certificate =
      lab.add_subcommand("certificate", "A certificate as the lab stored it when it was issued");
  certificate->add_option("number", cert->number, "Certificate number")->required();
  certificate->add_option("--format", cert->format, "html or text")
      ->check(CLI::IsMember({"html", "text"}))
      ->capture_default_str();
  certificate->add_option("-o,--output", cert->output_path, "Write here instead of standard output");
  certificate->callback([cert] { RunCertificate(*cert); });

  auto serial = std::make_shared<std::string>();
  auto type = std::make_shared<std::string>();
  CLI::App* device =
      lab.add_subcommand("device", "A lab manager sets a device's type (its recalibration interval)");
  device->add_option("serial", *serial, "Device serial")->required();
  device->add_option("--type", *type, "Device type (see device-type)")->required();
  device->callback([serial, type] {
    LabStore::Connect()->SetDeviceType(*serial, *type);
    std::cout << fmt::format("device {} is of type {}\n", *serial, *type);
  });

  auto type_name = std::make_shared<std::string>();
  auto interval = std::make_shared<std::string>();
  CLI::App* device_type =
      lab.add_subcommand("device-type", "A lab manager sets a device type's recalibration interval");
  device_type->add_option("type", *type_name, "Device type, e.g. MMA7260Q")->required();
  device_type->add_option("--interval", *interval, "Recalibration interval: 365d, 52w, 1y")->required();
  device_type->callback([type_name, interval] {
    const long days = DaysOption(*interval, "--interval");
    LabStore::Connect()->SetDeviceTypeInterval(*type_name, static_cast<int>(days));
    std::cout << fmt::format("device type {}: recalibrated every {} days\n", *type_name, days);
  });
}

}  // namespace

void SetupLabCommand(CLI::App& app) {
  CLI::App* lab = app.add_subcommand(
      "lab",
      "The lab's store: one PostgreSQL database every bench publishes its finished calibrations\n"
      "to, with lab-wide certificate numbers, device histories, recalibration due dates and the\n"
      "equipment register (docs/lab.md). The connection is libpq's own settings: PGHOST,\n"
      "PGPORT, PGDATABASE, PGUSER or PGSERVICE, passwords in ~/.pgpass; accelcal takes none.\n\n"
      "Examples:\n"
      "  accelcal lab publish                   # every finished session not yet published\n"
      "  accelcal lab history SIM-0001 --format json\n"
      "  accelcal lab due --within 30d\n"
      "  accelcal lab equipment --check TT-01 RUL-01");
  lab->require_subcommand(1);
  SetupLabPublishCommand(*lab);
  SetupLabHistoryCommand(*lab);
  SetupLabDueCommand(*lab);
  SetupLabEquipmentCommand(*lab);
  SetupAdministration(*lab);
}

}  // namespace accelcal::cli
