// `accelcal lab history|due|equipment`: reading the lab's register, and keeping its equipment.
#include <functional>
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include "accelcal/base/utc_time.h"
#include "accelcal/app/lab_equipment_check.h"
#include "accelcal/base/duration_text.h"
#include "accelcal/base/error.h"
#include "accelcal/io/lab_register_json.h"
#include "accelcal/lab/lab_store.h"
#include "cli/lab_commands.h"
#include "cli/output.h"

namespace accelcal::cli {
namespace {

std::string OrDash(const std::string& text) { return text.empty() ? "-" : text; }

// --format text|json, for the register's listings.
void AddFormatOption(CLI::App* sub, std::string* format) {
  sub->add_option("--format", *format, "text or json")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
}

std::string HistoryText(const LabHistory& h) {
  std::string t =
      fmt::format("device {} ({}): {} certificate(s)\n", h.serial,
                  h.device_type.empty() ? "no type: the lab's default interval" : "type " + h.device_type,
                  h.entries.size());
  t += fmt::format("{:<14} {:<19}  {:<10} {:<9} {:<12} {}\n", "certificate", "date (UTC)", "verdict",
                   "status", "bench", "session");
  for (const LabHistoryEntry& e : h.entries) {
    t += fmt::format("{:<14} {:<19}  {:<10} {:<9} {:<12} {}\n", e.certificate_number, ShortUtc(e.date_utc),
                     e.verdict, e.status, e.bench, e.session);
    if (!e.approved_by.empty())
      t += fmt::format("  approved {} by {}\n", ShortUtc(e.approved_utc), e.approved_by);
    if (!e.withdrawn_by.empty())
      t += fmt::format("  withdrawn {} by {}: {}\n", ShortUtc(e.withdrawn_utc), e.withdrawn_by,
                       e.withdrawn_reason);
  }
  return t;
}

std::string WhenText(const std::optional<long>& days_left, const std::string& due_date) {
  if (!days_left) return "no valid calibration: due now";
  if (*days_left < 0) return fmt::format("overdue by {} day(s) (due {})", -*days_left, due_date);
  if (*days_left == 0) return fmt::format("due today ({})", due_date);
  return fmt::format("due in {} day(s) ({})", *days_left, due_date);
}

std::string DueText(const LabDueList& due) {
  if (due.items.empty())
    return fmt::format("nothing due within {} day(s) of {} (UTC)\n", due.within_days, due.today);
  std::string t = fmt::format("due within {} day(s) of {} (UTC):\n", due.within_days, due.today);
  for (const LabDueItem& i : due.items) {
    const bool device = i.kind == LabDueItem::Kind::kDevice;
    const std::string last =
        i.last.empty()
            ? ""
            : fmt::format("; last {} of {}", device ? "certificate" : "calibration, certificate", i.last) +
                  (i.last_date.empty() ? "" : " on " + i.last_date);
    t += fmt::format(
        "{:<9}  {:<14} {}{}{}\n", device ? "device" : "equipment", i.id, WhenText(i.days_left, i.due_date),
        i.type.empty() ? "" : fmt::format(" [{}{}]", i.type, i.name.empty() ? "" : ": " + i.name), last);
  }
  return t;
}

std::string EquipmentText(const std::vector<LabEquipmentStatus>& items) {
  if (items.empty())
    return "the lab's equipment register is empty (a lab manager adds items with `accelcal lab equipment "
           "add`)\n";
  std::string t = fmt::format("{:<12} {:<10} {:<28} {:<14} {:<10}  {:<10}  {}\n", "id", "kind", "name",
                              "certificate", "calibrated", "valid until", "state");
  for (const LabEquipmentStatus& s : items) {
    std::string state = !s.registered      ? "not registered"
                        : !s.days_left     ? "no certificate"
                        : *s.days_left < 0 ? fmt::format("EXPIRED {} day(s) ago", -*s.days_left)
                                           : fmt::format("valid, {} day(s) left", *s.days_left);
    t += fmt::format("{:<12} {:<10} {:<28} {:<14} {:<10}  {:<11} {}\n", s.id, OrDash(s.kind), OrDash(s.name),
                     OrDash(s.certificate_ref), OrDash(s.calibrated_on), OrDash(s.valid_until), state);
  }
  return t;
}

// Opens the lab's store (LabStore::Connect).
using LabConnect = std::function<std::unique_ptr<LabStore>()>;

// A listing of the lab's register: the subcommand `name` of `lab`, its own options bound by
// `bind` (to what `query` reads), then --format; it prints what `query` reads as `text` or
// `json`. `query` connects (through its argument) once its options are checked: a wrong option
// is said without asking the lab.
template <class Result>
CLI::App* AddLabQuery(CLI::App& lab, const std::string& name, const std::string& description,
                      const std::function<void(CLI::App*)>& bind, std::function<Result(const LabConnect&)> query,
                      std::string (*text)(const Result&), std::string (*json)(const Result&)) {
  auto format = std::make_shared<std::string>("text");
  CLI::App* sub = lab.add_subcommand(name, description);
  bind(sub);
  AddFormatOption(sub, format.get());
  sub->callback([format, query = std::move(query), text, json] {
    const Result result = query([] { return LabStore::Connect(); });
    std::cout << (*format == "json" ? json(result) : text(result));
  });
  return sub;
}

struct EquipmentOptions {
  std::vector<std::string> check;
  std::string format = "text";
  LabEquipmentRegistration add;
};

void RunEquipment(const EquipmentOptions& o) {
  const std::unique_ptr<LabStore> lab = LabStore::Connect();
  if (o.check.empty()) {
    const std::vector<LabEquipmentStatus> items = lab->Equipment();
    std::cout << (o.format == "json" ? LabEquipmentJsonText(items) : EquipmentText(items));
    return;
  }
  const EquipmentCheck check = CheckEquipment(*lab, o.check);
  if (o.format == "json") {
    std::cout << LabEquipmentJsonText(check.items);
  } else {
    for (const std::string& w : check.warnings) std::cout << "warning: " << w << "\n";
    if (check.warnings.empty())
      std::cout << fmt::format("all {} item(s) calibrated, none running out within {} days\n",
                               check.items.size(), kEquipmentSoonDays);
  }
  if (check.any_expired_or_unknown) throw Error("equipment expired or unknown to the lab (said above)");
}

}  // namespace

void SetupLabHistoryCommand(CLI::App& lab) {
  auto serial = std::make_shared<std::string>();
  AddLabQuery<LabHistory>(
      lab, "history", "Every certificate of a device across the lab's benches, withdrawn ones included",
      [serial](CLI::App* sub) { sub->add_option("serial", *serial, "Device serial")->required(); },
      [serial](const LabConnect& connect) { return connect()->History(*serial); }, &HistoryText, &LabHistoryJsonText);
}

void SetupLabDueCommand(CLI::App& lab) {
  auto within = std::make_shared<std::string>("30d");
  AddLabQuery<LabDueList>(
      lab, "due",
      "Devices and equipment due for recalibration: a device its type's interval (else the\n"
      "lab's default) after its last valid calibration, an item of equipment when its\n"
      "certificate runs out; overdue ones first",
      [within](CLI::App* sub) {
        sub->add_option("--within", *within, "Window from today: 30d, 6w, 1y (default 30d)");
      },
      [within](const LabConnect& connect) {
        const std::optional<long> days = ParseDays(*within);
        if (!days) throw Error(fmt::format("--within {}: give days, weeks or years (30d, 6w, 1y)", *within));
        return connect()->Due(static_cast<int>(*days));
      },
      &DueText, &LabDueJsonText);
}

void SetupLabEquipmentCommand(CLI::App& lab) {
  auto o = std::make_shared<EquipmentOptions>();
  CLI::App* sub = lab.add_subcommand(
      "equipment",
      "The lab's equipment (rulers, turntables, levels, prisms) and their calibration\n"
      "certificates; --check ID... warns of items expired, running out within 30 days, or\n"
      "unknown (exit 1 for expired or unknown: what the wizard's welcome checks)");
  sub->add_option("--check", o->check, "Equipment ids to check");
  AddFormatOption(sub, &o->format);
  sub->callback([o] {
    if (o->add.id.empty()) RunEquipment(*o);
  });
  CLI::App* add = sub->add_subcommand(
      "add", "A lab manager registers an item, or a new certificate of one (the older ones stay)");
  LabEquipmentRegistration& r = o->add;
  add->add_option("id", r.id, "Equipment id, as the procedures' [equipment] name it (id = ...)")->required();
  add->add_option("--kind", r.kind, "ruler, turntable, level, prism, ...")->required();
  add->add_option("--name", r.name, "What it is")->required();
  add->add_option("--certificate", r.certificate_ref, "Its calibration certificate's reference")->required();
  add->add_option("--calibrated", r.calibrated_on, "Date of that calibration, YYYY-MM-DD")->required();
  add->add_option("--valid-until", r.valid_until, "Date the certificate runs out, YYYY-MM-DD")->required();
  add->add_option("--issuer", r.issuer, "Who calibrated it");
  add->callback([o] {
    LabStore::Connect()->RegisterEquipment(o->add);
    std::cout << fmt::format("equipment {} registered: certificate {}, valid until {}\n", o->add.id,
                             o->add.certificate_ref, o->add.valid_until);
  });
}

}  // namespace accelcal::cli
