// `accelcal history DEVICE`: every calibration of a device in a session directory, its
// parameters over time and how far each moved since the previous one
// (src/accelcal/session/device_history.h).
#include <cmath>
#include <iostream>
#include <memory>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "accelcal/base/error.h"
#include "accelcal/app/device_history.h"
#include "accelcal/io/history_json.h"
#include "accelcal/session/session_paths.h"
#include "cli/commands.h"
#include "cli/output.h"

namespace accelcal::cli {
namespace {

struct HistoryCommandOptions {
  std::string device;
  std::string sessions_dir;  // empty: the default directory
  std::string format = "text";
};

std::string Text(const DeviceHistory& h) {
  std::string t = fmt::format("device {}: {} calibration(s) in {}", h.device, h.entries.size(), h.dir);
  if (h.sessions_without_result > 0)
    t += fmt::format(" ({} session(s) without a calibration not shown)", h.sessions_without_result);
  t += fmt::format("\nmoves are since the previous calibration, in units and in sigmas of the combined "
                   "1-sigma; over {} sigmas: changed\n", kChangedSigmas);
  for (const HistoryEntry& e : h.entries) {
    t += fmt::format("\n{} UTC  session {}\n", ShortUtc(e.session.created_utc), e.session.name);
    t += fmt::format("  {:<9} {:>16} {:>12} {:>14} {:>9}  {}\n", "parameter", "value", "1-sigma", "moved",
                     "sigmas", "unit");
    const auto p = e.calibration.model.ToVector(), s = e.calibration.uncertainty.ToVector();
    std::vector<std::string> changed;
    for (int i = 0; i < kNumBaseParameters; ++i) {
      std::string moved = "-", sigmas = "-", flag;
      if (!e.moves.empty()) {
        const ParameterMove& m = e.moves[static_cast<size_t>(i)];
        moved = fmt::format("{:+.6g}", m.delta);
        sigmas = std::isfinite(m.n_sigmas) ? fmt::format("{:.1f}", m.n_sigmas) : "inf";
        if (m.changed) {
          flag = "  changed";
          changed.emplace_back(ParameterName(i));
        }
      }
      t += fmt::format("  {:<9} {:>16.10g} {:>12.3g} {:>14} {:>9}  {}{}\n", ParameterName(i), p(i), s(i),
                       moved, sigmas, ParameterUnit(i), flag);
    }
    if (!e.moves.empty())
      t += changed.empty() ? std::string("  no parameter changed beyond its uncertainty\n")
                           : fmt::format("  changed: {}\n", fmt::join(changed, ", "));
  }
  return t;
}

void RunHistory(const HistoryCommandOptions& o) {
  const std::string dir = o.sessions_dir.empty() ? DefaultSessionDir() : o.sessions_dir;
  const DeviceHistory h = BuildDeviceHistory(dir, o.device);
  if (o.format == "json")
    std::cout << DeviceHistoryJsonText(h);
  else
    std::cout << Text(h);
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
