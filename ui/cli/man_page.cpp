#include "cli/man_page.h"

#include <algorithm>
#include <cctype>

#include <fmt/core.h>

namespace accelcal::cli {
namespace {

// CLI11's own formatter, for the option columns exactly as --help prints them.
class HelpColumns : public CLI::Formatter {
 public:
  // "-o,--output" and " TEXT REQUIRED" (type, default, REQUIRED, Needs/Excludes).
  std::string Name(const CLI::Option* opt, bool positional) const { return make_option_name(opt, positional); }
  std::string Details(const CLI::Option* opt) const { return make_option_opts(opt); }
  // The usage line without its label: "accelcal wizard [OPTIONS]".
  std::string Usage(const CLI::App* app, const std::string& name) const {
    std::string usage = make_usage(app, name);
    const size_t start = usage.find(name);
    usage = usage.substr(start == std::string::npos ? 0 : start);
    while (!usage.empty() && usage.back() == '\n') usage.pop_back();
    return usage;
  }
};

std::vector<std::string> TextLines(std::string_view text) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find('\n', start), text.size());
    std::string line(text.substr(start, end - start));
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
    lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

// One line of text in roff: backslashes escaped; minus signs and quotes as the ASCII characters
// (left alone, '-' may be shown as a hyphen and quotes as typographic ones, and an option or a
// command copied from the page would not work); a leading '.' made text.
std::string RoffEscape(std::string_view line) {
  std::string out;
  for (const char c : line) {
    if (c == '\\') out += "\\e";
    else if (c == '-') out += "\\-";
    else if (c == '\'') out += "\\(aq";
    else if (c == '`') out += "\\(ga";
    else out += c;
  }
  if (!out.empty() && out[0] == '.') out.insert(0, "\\&");
  return out;
}

// "Examples:", "Exit status:": a short capitalised line ending in ':'.
bool IsHeading(const std::string& line) {
  if (line.size() < 2 || line.size() > 30 || line.back() != ':' || !std::isupper(static_cast<unsigned char>(line[0])))
    return false;
  if (line.find(':') != line.size() - 1) return false;
  return std::count(line.begin(), line.end(), ' ') <= 2;
}

bool Indented(const std::string& line) { return !line.empty() && (line[0] == ' ' || line[0] == '\t'); }

std::string UpperCase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

void RoffSection(std::string& out, std::string_view title) { out += fmt::format(".SH {}\n", title); }

// The options of `app` (positionals first, then each group, as --help lists them) as tagged
// paragraphs; `sections`: each under its own .SH (ARGUMENTS, OPTIONS), else under a text line.
void RoffOptions(std::string& out, const CLI::App& app, bool sections) {
  const HelpColumns columns;
  const auto item = [&](const CLI::Option* opt, bool positional) {
    out += ".TP\n";
    out += fmt::format("\\fB{}\\fR{}\n", RoffEscape(columns.Name(opt, positional)), RoffEscape(columns.Details(opt)));
    out += RoffText(opt->get_description(), false);
  };
  const auto heading = [&](const std::string& title) {
    if (sections) RoffSection(out, UpperCase(title));
    else out += fmt::format(".PP\n{}:\n", RoffEscape(title));
  };
  const std::vector<const CLI::Option*> positionals =
      app.get_options([](const CLI::Option* o) { return !o->get_group().empty() && o->get_positional(); });
  if (!positionals.empty()) {
    heading(sections ? "Arguments" : "Positionals");
    for (const CLI::Option* opt : positionals) item(opt, true);
  }
  for (const std::string& group : app.get_groups()) {
    const std::vector<const CLI::Option*> opts = app.get_options(
        [&group](const CLI::Option* o) { return o->get_group() == group && o->nonpositional(); });
    if (group.empty() || opts.empty()) continue;
    heading(group);
    for (const CLI::Option* opt : opts) item(opt, false);
  }
}

// A command's subcommands (and theirs), each a subsection of its page.
void RoffSubcommands(std::string& out, const CLI::App& app, const std::string& path) {
  for (const CLI::App* sub : VisibleCommands(app)) {
    const std::string name = path + " " + sub->get_name();
    out += fmt::format(".SS \"{}\"\n", RoffEscape(name));
    out += fmt::format("\\fB{}\\fR\n.PP\n", RoffEscape(HelpColumns().Usage(sub, name)));
    out += RoffText(sub->get_description(), false);
    RoffOptions(out, *sub, false);
    if (!sub->get_footer().empty()) out += ".PP\n" + RoffText(sub->get_footer(), false);
    RoffSubcommands(out, *sub, name);
  }
}

std::string PageName(const CLI::App& root, const CLI::App* command) {
  return command == nullptr ? root.get_name() : root.get_name() + "-" + command->get_name();
}

std::string RoffHeader(const std::string& name, const std::string& summary, const ManPageContext& context) {
  return fmt::format(".TH \"{}\" \"1\" \"\" \"{}\" \"accelcal manual\"\n.SH NAME\n{} \\- {}\n",
                     UpperCase(name), context.version, RoffEscape(name), RoffEscape(summary));
}

void RoffSeeAlso(std::string& out, const std::vector<std::string>& pages) {
  RoffSection(out, "SEE ALSO");
  std::vector<std::string> items;
  for (const std::string& page : pages) {
    const size_t paren = page.find('(');
    items.push_back(fmt::format("\\fB{}\\fR{}", RoffEscape(page.substr(0, paren)), page.substr(paren)));
  }
  for (size_t i = 0; i < items.size(); ++i) out += items[i] + (i + 1 < items.size() ? ",\n" : "\n");
}

// Text that opens with a heading makes its own section; other text goes under `fallback`.
void RoffBlock(std::string& out, const std::string& text, std::string_view fallback) {
  if (text.empty()) return;
  const std::vector<std::string> lines = TextLines(text);
  const bool own_heading = lines.size() > 1 && IsHeading(lines[0]) && Indented(lines[1]);
  if (!own_heading) RoffSection(out, fallback);
  out += RoffText(text, true);
}

ManPage RootPage(const CLI::App& root, const ManPageContext& context) {
  const std::string name = PageName(root, nullptr);
  // "accelcal: calibrate ...": the summary is what follows the program's name.
  const std::string full_description = root.get_description();
  std::string_view description = full_description;
  if (description.rfind(name + ": ", 0) == 0) description.remove_prefix(name.size() + 2);
  std::string out = RoffHeader(name, Summary(description), context);
  RoffSection(out, "SYNOPSIS");
  out += fmt::format("\\fB{}\\fR\n", RoffEscape(HelpColumns().Usage(&root, name)));
  RoffBlock(out, root.get_description(), "DESCRIPTION");
  RoffOptions(out, root, true);
  RoffSection(out, "COMMANDS");
  std::vector<std::string> see_also;
  for (const CLI::App* command : VisibleCommands(root)) {
    const std::string page = PageName(root, command);
    out += fmt::format(".TP\n\\fB{}\\fR\n{}\n.br\nSee \\fB{}\\fR(1).\n", RoffEscape(command->get_name()),
                       RoffEscape(Summary(command->get_description())), RoffEscape(page));
    see_also.push_back(page + "(1)");
  }
  RoffBlock(out, root.get_footer(), "NOTES");
  see_also.insert(see_also.end(), context.see_also.begin(), context.see_also.end());
  RoffSeeAlso(out, see_also);
  return {name, 1, out};
}

ManPage CommandPage(const CLI::App& root, const CLI::App& command, const ManPageContext& context) {
  const std::string name = PageName(root, &command);
  const std::string path = root.get_name() + " " + command.get_name();
  std::string out = RoffHeader(name, Summary(command.get_description()), context);
  RoffSection(out, "SYNOPSIS");
  out += fmt::format("\\fB{}\\fR\n", RoffEscape(HelpColumns().Usage(&command, path)));
  RoffBlock(out, command.get_description(), "DESCRIPTION");
  RoffOptions(out, command, true);
  if (!VisibleCommands(command).empty()) {
    RoffSection(out, "COMMANDS");
    RoffSubcommands(out, command, path);
  }
  RoffBlock(out, command.get_footer(), "NOTES");
  std::vector<std::string> see_also{root.get_name() + "(1)"};
  see_also.insert(see_also.end(), context.see_also.begin(), context.see_also.end());
  RoffSeeAlso(out, see_also);
  return {name, 1, out};
}

}  // namespace

std::vector<const CLI::App*> VisibleCommands(const CLI::App& app) {
  return app.get_subcommands([](const CLI::App* sub) {
    return !sub->get_group().empty() && !sub->get_name().empty() && !sub->get_disabled();
  });
}

std::string RoffText(std::string_view text, bool headings) {
  const std::vector<std::string> lines = TextLines(text);
  std::string out;
  bool no_fill = false;
  bool paragraph_due = false;
  const auto fill = [&](bool on) {
    if (on && no_fill) out += ".fi\n";
    if (!on && !no_fill) out += ".nf\n";
    no_fill = !on;
  };
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (line.empty()) {
      paragraph_due = !out.empty();
      continue;
    }
    if (headings && IsHeading(line) && i + 1 < lines.size() && Indented(lines[i + 1])) {
      fill(true);
      RoffSection(out, UpperCase(line.substr(0, line.size() - 1)));
      paragraph_due = false;
      continue;
    }
    if (paragraph_due) {
      fill(true);
      out += ".PP\n";
      paragraph_due = false;
    }
    fill(!Indented(line));
    out += RoffEscape(line) + "\n";
  }
  fill(true);
  return out;
}

std::string Summary(std::string_view description) {
  std::string text(description.substr(0, description.find("\n\n")));
  std::replace(text.begin(), text.end(), '\n', ' ');
  int depth = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '(') ++depth;
    if (c == ')') depth = std::max(0, depth - 1);
    const bool ends = i + 1 == text.size() || text[i + 1] == ' ';
    if (depth == 0 && ends && (c == '.' || c == ':')) return text.substr(0, i);
  }
  return text;
}

std::vector<ManPage> ManPages(const CLI::App& root, const ManPageContext& context) {
  std::vector<ManPage> pages{RootPage(root, context)};
  for (const CLI::App* command : VisibleCommands(root)) pages.push_back(CommandPage(root, *command, context));
  return pages;
}

}  // namespace accelcal::cli
