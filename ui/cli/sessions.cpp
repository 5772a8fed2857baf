// `accelcal sessions`: lists the sessions in the default directory or in the given
// directories and files, one line each.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include <fmt/core.h>

#include "accelcal/base/utc_time.h"
#include "accelcal/base/error.h"
#include "accelcal/session/session_catalog.h"
#include "accelcal/session/session_paths.h"
#include "accelcal/session/session_store.h"
#include "cli/commands.h"
#include "cli/output.h"

namespace accelcal::cli {
namespace {

namespace fs = std::filesystem;

struct SessionsCommandOptions {
  std::vector<std::string> paths;  // directories or session files; empty: the default directory
};

constexpr const char* kRowFormat = "{:<22} {:<20} {:<14} {:<12} {:<14} {:>8} {:<5} {}\n";
constexpr size_t kNameWidth = 22;

// `text` cut to `width` characters, its end replaced by "..." when cut, so that a long device,
// operator or procedure title keeps the columns after it in place.
std::string Cell(const std::string& text, size_t width) {
  if (text.empty()) return "-";
  if (text.size() <= width) return text;
  return text.substr(0, width - 3) + "...";
}

// The name is what the user types back (accelcal report NAME): never cut. A longer one goes on a
// line of its own, the row under it.
std::string NameLines(const std::string& name, std::string row_after_name) {
  if (name.size() <= kNameWidth) return fmt::format("{:<{}}", name, kNameWidth) + row_after_name;
  return name + "\n" + std::string(kNameWidth, ' ') + row_after_name;
}

// One line for a session; one line with the reason for a file that cannot be read as one.
std::string Row(const std::string& path) {
  SessionOpenOptions read_only;
  read_only.read_only = true;
  try {
    const SessionInfo info = SessionStore::Open(path, read_only)->Info();
    const std::string created = ShortUtc(info.created_utc);
    const std::string row = fmt::format(kRowFormat, "", created, Cell(info.device, 14),
                                        Cell(info.operator_name, 12), Cell(info.procedure, 14),
                                        info.num_captures, SessionStateToString(info.state),
                                        info.has_result ? "yes" : "no");
    return NameLines(info.name, row.substr(kNameWidth));
  } catch (const Error& e) {
    return fmt::format("{:<22} unreadable: {}\n", fs::path(path).stem().string(), e.what());
  }
}

void RunSessions(const SessionsCommandOptions& o) {
  std::vector<std::string> args = o.paths;
  if (args.empty()) {
    args.push_back(DefaultSessionDir());
    if (!fs::is_directory(args[0])) {
      std::cout << fmt::format("no sessions yet (they go to {})\n", args[0]);
      return;
    }
  }
  std::vector<std::string> files;
  for (const std::string& arg : args) {
    if (fs::is_directory(arg)) {
      for (const std::string& f : SessionFilesIn(arg)) files.push_back(f);
    } else if (fs::is_regular_file(arg)) {
      files.push_back(arg);
    } else {
      throw Error(fmt::format("no session or directory {}", arg));
    }
  }
  if (files.empty()) {
    std::cout << "no sessions\n";
    return;
  }
  std::cout << fmt::format(kRowFormat, "name", "created (UTC)", "device", "operator", "procedure",
                           "captures", "state", "calibration");
  for (const std::string& f : files) std::cout << Row(f);
}

}  // namespace

void SetupSessionsCommand(CLI::App& app) {
  auto opts = std::make_shared<SessionsCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "sessions",
      "List calibration sessions: name, creation time, device, operator, procedure, captures\n"
      "accepted, state (open/done) and whether it has a calibration. By default the sessions in\n"
      "$XDG_DATA_HOME/accelcal/sessions (~/.local/share/accelcal/sessions); works while a wizard\n"
      "is running.\n\n"
      "Examples:\n"
      "  accelcal sessions\n"
      "  accelcal sessions /mnt/bench/sessions s.db");
  sub->add_option("paths", opts->paths, "Session directories or session files");
  sub->callback([opts] { RunSessions(*opts); });
}

}  // namespace accelcal::cli
