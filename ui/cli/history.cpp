// `accelcal history DEVICE`: every calibration of a device in a session directory, its
// parameters over time and how far each moved since the previous one
// (app/device_history.h builds it, report/history_text.h writes it as text).
#include <iostream>
#include <memory>

#include "accelcal/app/device_history.h"
#include "accelcal/io/history_json.h"
#include "accelcal/report/history_text.h"
#include "cli/commands.h"

namespace accelcal::cli {
namespace {

struct HistoryCommandOptions {
  std::string device;
  std::string sessions_dir;  // empty: the default directory
  std::string format = "text";
};

void RunHistory(const HistoryCommandOptions& o) {
  const DeviceHistory h = BuildDeviceHistory(o.sessions_dir, o.device);
  std::cout << (o.format == "json" ? DeviceHistoryJsonText(h) : FormatHistoryText(h));
}

}  // namespace

void SetupHistoryCommand(CLI::App& app) {
  auto opts = std::make_shared<HistoryCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "history",
      "Every calibration of a device (sessions with a result, by creation date): bias, scale and\n"
      "misalignment with their 1-sigma, and how far each moved since the previous calibration,\n"
      "in units and in sigmas of the combined uncertainty (over 3: changed).\n\n"
      "Examples:\n"
      "  accelcal history SIM-0001\n"
      "  accelcal history BOARD-7 --sessions-dir /mnt/bench/sessions --format json");
  sub->add_option("device", opts->device, "Device serial (as recorded in the sessions)")->required();
  sub->add_option("--sessions-dir", opts->sessions_dir,
                  "Session directory (default $XDG_DATA_HOME/accelcal/sessions)");
  sub->add_option("--format", opts->format, "text or json")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  sub->callback([opts] { RunHistory(*opts); });
}

}  // namespace accelcal::cli
