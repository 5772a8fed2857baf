// The manual pages of `accelcal`, written from the command line's own definition: the same
// descriptions, option names, value types, defaults and footers that --help prints (CLI11's
// formatter supplies the option columns), so a page cannot disagree with --help. One page per
// command (accelcal(1), accelcal-wizard(1), ...), found by walking the CLI: a command added later
// gets its page without an edit here. A command's own subcommands are sections of its page.
//
// Text conventions read from the help texts: a blank line starts a paragraph; indented lines are
// kept as typed (examples, tables); a short heading line ending in ':' ("Examples:", "Exit
// status:") followed by indented lines becomes a section of the page (EXAMPLES, EXIT STATUS).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace accelcal::cli {

struct ManPage {
  std::string name;  // "accelcal-wizard"
  int section = 1;
  std::string roff;  // the page's source (man(7) macros)
};

struct ManPageContext {
  std::string version;                // "accelcal 0.1.0 (git 68dabc6)", the pages' footer
  std::vector<std::string> see_also;  // other pages named under SEE ALSO: "accelcal-procedure(5)"
};

// accelcal(1) and one page per command `root` shows in its --help, in that order.
std::vector<ManPage> ManPages(const CLI::App& root, const ManPageContext& context);

// The commands that have pages (and completion): those --help lists, not the hidden ones.
std::vector<const CLI::App*> VisibleCommands(const CLI::App& app);

// `text` as roff text lines (escapes; see the conventions above). `headings`: a heading line
// becomes a .SH section; false keeps it as a text line (inside a command's subsection).
std::string RoffText(std::string_view text, bool headings);

// The first sentence of a command's description: the whatis line of its page.
std::string Summary(std::string_view description);

}  // namespace accelcal::cli
