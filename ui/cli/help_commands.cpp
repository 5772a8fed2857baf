// The hidden commands the build runs to write what is installed beside the program, each from the
// command line's own definition (so it cannot disagree with --help), and one the completion asks:
//   accelcal help-man --dir DIR [--also PAGE]...   the manual pages, DIR/man1/accelcal*.1
//   accelcal help-man [COMMAND]                    one page on standard output ('' accelcal(1))
//   accelcal help-completion [-o FILE]             the bash completion script
//   accelcal help-shipped procedures|scenarios     the shipped files' names, one a line
// Hidden: --help does not list them, and they get no page and no completion.
#include <filesystem>
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "cli/commands.h"
#include "cli/completion_script.h"
#include "cli/man_page.h"
#include "cli/output.h"
#include "cli/shipped_files.h"

namespace accelcal::cli {
namespace {

struct HelpManOptions {
  std::string dir;
  std::vector<std::string> also;
  std::string command;
};

void RunHelpMan(const CLI::App& root, const std::string& version, const HelpManOptions& o) {
  const std::vector<ManPage> pages = ManPages(root, {version, o.also});
  if (o.dir.empty()) {
    const std::string wanted = o.command.empty() ? root.get_name() : root.get_name() + "-" + o.command;
    for (const ManPage& page : pages)
      if (page.name == wanted) return WriteOutputText("", page.roff);
    throw Error(fmt::format("no manual page for '{}'", o.command));
  }
  const std::filesystem::path dir = std::filesystem::path(o.dir) / "man1";
  std::filesystem::create_directories(dir);
  for (const ManPage& page : pages)
    WriteOutputText((dir / fmt::format("{}.{}", page.name, page.section)).string(), page.roff);
}

CLI::App* Hidden(CLI::App& app, const std::string& name, const std::string& what) {
  CLI::App* sub = app.add_subcommand(name, what);
  sub->group("");
  return sub;
}

}  // namespace

void SetupHelpCommands(CLI::App& app, const std::string& version) {
  auto man = std::make_shared<HelpManOptions>();
  CLI::App* help_man = Hidden(app, "help-man", "Write the manual pages");
  help_man->add_option("command", man->command, "The command whose page to print");
  help_man->add_option("--dir", man->dir, "Write every page under DIR/man1");
  help_man->add_option("--also", man->also, "A page named under SEE ALSO, e.g. accelcal-procedure(5)");
  help_man->callback([&app, version, man] { RunHelpMan(app, version, *man); });

  auto completion_path = std::make_shared<std::string>();
  CLI::App* completion = Hidden(app, "help-completion", "Write the bash completion script");
  completion->add_option("-o,--output", *completion_path, "File to write (default: standard output)");
  completion->callback([&app, completion_path] {
    WriteOutputText(*completion_path, BashCompletionScript(app, app.get_name()));
  });

  auto kind = std::make_shared<std::string>();
  CLI::App* shipped = Hidden(app, "help-shipped", "List the shipped procedures or scenarios");
  shipped->add_option("kind", *kind, "procedures or scenarios")
      ->required()
      ->check(CLI::IsMember({std::string(kShippedProcedures), std::string(kShippedScenarios)}));
  shipped->callback([kind] {
    std::string names;
    for (const std::string& name : ShippedNames(*kind)) names += name + "\n";
    WriteOutputText("", names);
  });
}

}  // namespace accelcal::cli
