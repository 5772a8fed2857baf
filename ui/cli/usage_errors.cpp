#include "cli/usage_errors.h"

#include <algorithm>
#include <cstdio>
#include <iostream>

#include <fmt/core.h>

#include "accelcal/base/safe_text.h"

namespace accelcal::cli {
namespace {

// Levenshtein distance (insertions, deletions, substitutions each 1).
size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

void AddNames(const CLI::App& app, std::vector<std::string>& names) {
  for (const CLI::Option* opt : app.get_options())
    for (const std::string& name : opt->get_lnames()) names.push_back("--" + name);
}

// The first word on the command line that `app` did not take, as typed: an option's name without
// its "=value", or a word.
std::vector<std::string> Unexpected(const std::vector<std::string>& args,
                                    const std::vector<std::string>& known) {
  std::vector<std::string> out;
  for (const std::string& arg : args) {
    if (arg.rfind("--", 0) != 0) continue;
    const std::string name = arg.substr(0, arg.find('='));
    if (name != "--" && std::find(known.begin(), known.end(), name) == known.end())
      out.push_back(name);
  }
  return out;
}

}  // namespace

std::string NearestName(std::string_view typed, const std::vector<std::string>& known) {
  std::string best;
  size_t best_distance = 0;
  const std::string_view bare = typed.substr(typed.find_first_not_of('-') == std::string_view::npos
                                                 ? 0
                                                 : typed.find_first_not_of('-'));
  const size_t limit = bare.size() <= 4 ? 1 : 2;
  for (const std::string& name : known) {
    const size_t d = EditDistance(typed, name);
    if (d == 0 || d > limit) continue;
    if (best.empty() || d < best_distance) {
      best = name;
      best_distance = d;
    }
  }
  return best;
}

std::vector<std::string> KnownNames(const CLI::App& app) {
  std::vector<std::string> names;
  AddNames(app, names);
  for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
  std::vector<const CLI::App*> parsed;
  for (const CLI::App* sub : app.get_subcommands()) parsed.push_back(sub);
  // Nothing parsed (the error came before a subcommand): every subcommand's options.
  if (parsed.empty())
    for (const CLI::App* sub : app.get_subcommands({})) parsed.push_back(sub);
  for (const CLI::App* sub : parsed) AddNames(*sub, names);
  return names;
}

int ReportParseError(const CLI::App& app, const CLI::ParseError& e, const std::vector<std::string>& args) {
  const std::string name = e.get_name();
  if (name == "CallForHelp" || name == "CallForAllHelp" || name == "CallForVersion") return app.exit(e);
  std::fflush(stdout);
  std::string message = DisplayLines(e.what());
  const std::vector<std::string> known = KnownNames(app);
  std::vector<std::string> suggestions;
  for (const std::string& typed : Unexpected(args, known)) {
    const std::string near = NearestName(typed, known);
    if (!near.empty()) suggestions.push_back(fmt::format("{}: did you mean {}?", typed, near));
  }
  // A mistyped subcommand is a word, not an option.
  if (app.get_subcommands().empty() && !args.empty() && args[0].rfind('-', 0) != 0) {
    const std::string near = NearestName(args[0], known);
    if (!near.empty() && near.rfind('-', 0) != 0)
      suggestions.push_back(fmt::format("{}: did you mean {}?", args[0], near));
  }
  fmt::print(stderr, "accelcal: error: {}\n", message);
  for (const std::string& s : suggestions) fmt::print(stderr, "accelcal: error: {}\n", s);
  const std::vector<CLI::App*> parsed = app.get_subcommands();
  fmt::print(stderr, "(accelcal {}--help lists the options)\n",
             parsed.empty() ? "" : parsed.back()->get_name() + " ");
  return kExitUsage;
}

}  // namespace accelcal::cli
