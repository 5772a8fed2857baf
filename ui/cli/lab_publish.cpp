// `accelcal lab publish [SESSION...]`: finished sessions to the lab's store (app/lab_publish.h).
// Without sessions named: the backlog, every finished session of the session directory not yet
// published (a bench offline for a week publishes it all when it is back).
#include <filesystem>
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include "accelcal/app/lab_publish.h"
#include "accelcal/base/error.h"
#include "accelcal/session/session_paths.h"
#include "cli/lab_commands.h"
#include "cli/output.h"

namespace accelcal::cli {
namespace {

struct PublishOptions {
  std::vector<std::string> sessions;  // paths or names; empty: the backlog of sessions_dir
  std::string sessions_dir;           // empty: the default directory
};

using Kind = SessionPublishOutcome::Kind;

void RunPublish(const PublishOptions& o) {
  std::vector<std::string> paths;
  for (const std::string& s : o.sessions) paths.push_back(ResolveSessionPath(s));
  if (o.sessions.empty()) {
    const std::string dir = o.sessions_dir.empty() ? DefaultSessionDir() : o.sessions_dir;
    if (!std::filesystem::is_directory(dir)) {
      if (!o.sessions_dir.empty()) throw Error(fmt::format("no session directory {}", dir));
      std::cout << fmt::format("nothing to publish: no sessions yet (they go to {})\n", dir);
      return;
    }
    paths = UnpublishedSessions(dir);
    if (paths.empty()) {
      std::cout << fmt::format("nothing to publish: every finished session in {} is in the lab's register\n",
                               dir);
      return;
    }
  }
  std::unique_ptr<LabStore> lab;
  try {
    lab = LabStore::Connect();
  } catch (const LabError& e) {
    if (!e.unreachable()) throw;
    throw Error(fmt::format("{}: {} session(s) wait, published by the next `accelcal lab publish`", e.what(),
                            paths.size()));
  }
  long failed = 0, published = 0, held = 0, waiting = 0;
  for (const SessionPublishOutcome& outcome :
       PublishSessionFiles(*lab, paths, ShippedProcedurePath("full_calibration.toml"))) {
    std::cout << DescribeOutcome(outcome) << "\n";
    published += outcome.kind == Kind::kPublished;
    held += outcome.kind == Kind::kAlreadyPublished;
    failed += outcome.kind == Kind::kFailed || outcome.kind == Kind::kNotReady;
    waiting += outcome.lab_unreachable;
  }
  std::cout << fmt::format("{} published, {} already in the register, {} not published ({})\n", published,
                           held, failed, lab->Identity());
  if (failed > 0)
    throw Error(waiting > 0 ? fmt::format("the lab store was lost: {} session(s) wait, published by the next "
                                          "`accelcal lab publish`",
                                          waiting)
                            : fmt::format("{} session(s) not published (said above)", failed));
}

}  // namespace

void SetupLabPublishCommand(CLI::App& lab) {
  auto opts = std::make_shared<PublishOptions>();
  CLI::App* sub = lab.add_subcommand(
      "publish",
      "Publish finished sessions to the lab's store: the session, its calibration, verdict,\n"
      "equipment, and the certificate with its lab-wide number, written back into the session\n"
      "and into the report beside it. Once only: publishing again changes nothing. Without\n"
      "SESSION: every finished session of the session directory not yet published.");
  sub->add_option("session", opts->sessions, "Session files, or names in the default directory");
  sub->add_option("--sessions-dir", opts->sessions_dir,
                  "Where the backlog is (default $XDG_DATA_HOME/accelcal/sessions)");
  sub->callback([opts] { RunPublish(*opts); });
}

}  // namespace accelcal::cli
