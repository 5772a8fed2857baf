#include "cli/usage_errors.h"

#include <algorithm>
#include <cstdio>
#include <initializer_list>
#include <iostream>
#include <optional>

#include <fmt/core.h>

#include "accelcal/base/safe_text.h"
#include "cli/cli_checks.h"
#include "cli/man_page.h"

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

// `text` split by `literals` in order: it must start with the first and end with the last (""
// for anything), and holds one captured piece between each two, e.g. {"", ": At Most ", "
// required but received ", ""} on "--speed: At Most 1 required but received 2" gives
// {"--speed", "1", "2"}. Empty when `text` is not of that form.
std::optional<std::vector<std::string>> MatchPieces(std::string_view text,
                                                    std::initializer_list<std::string_view> literals) {
  const std::vector<std::string_view> lit(literals);
  if (text.substr(0, lit[0].size()) != lit[0]) return std::nullopt;
  std::vector<std::string> pieces;
  size_t at = lit[0].size();
  for (size_t k = 1; k < lit.size(); ++k) {
    const bool last = k + 1 == lit.size();
    size_t next = last ? (lit[k].empty() ? text.size() : text.rfind(lit[k])) : text.find(lit[k], at);
    if (next == std::string_view::npos || next < at) return std::nullopt;
    if (last && next + lit[k].size() != text.size()) return std::nullopt;
    pieces.emplace_back(text.substr(at, next - at));
    at = next + lit[k].size();
  }
  return pieces;
}

// The command being parsed when the error came: the deepest parsed subcommand, else `app`.
const CLI::App& ActiveCommand(const CLI::App& app) {
  const CLI::App* active = &app;
  while (!active->get_subcommands().empty()) active = active->get_subcommands().back();
  return *active;
}

// "accelcal wizard".
std::string CommandPath(const CLI::App& command) {
  std::string path = command.get_name();
  for (const CLI::App* up = command.get_parent(); up != nullptr; up = up->get_parent())
    path = up->get_name() + " " + path;
  return path;
}

// The option CLI11 names ("--speed", "scenario") in the command or one of the commands above it.
const CLI::Option* NamedOption(const CLI::App& command, const std::string& name) {
  for (const CLI::App* app = &command; app != nullptr; app = app->get_parent())
    if (const CLI::Option* opt = app->get_option_no_throw(name)) return opt;
  return nullptr;
}

std::string JoinWords(const std::vector<std::string>& words, std::string_view last_joint) {
  std::string out;
  for (size_t i = 0; i < words.size(); ++i)
    out += (i == 0 ? "" : i + 1 == words.size() ? std::string(last_joint) : ", ") + words[i];
  return out;
}

// What a value of `opt` is, in words: "a number", "a whole number", "one of text, json".
std::string ValueWords(const CLI::Option* opt) {
  if (opt == nullptr) return "a value";
  const std::string type = opt->get_type_name();
  if (const std::vector<std::string> choices = OptionChoices(*opt); !choices.empty())
    return "one of " + JoinWords(choices, " or ");
  const std::string base = type.substr(0, type.find(':'));
  if (base == "FLOAT" || base == "NUMBER") return "a number";
  if (base == "INT") return "a whole number";
  if (base == "UINT") return "a whole number, 0 or more";
  return "a value";
}

// The first sentence of what `opt` is, for a message ("" when there is no description).
std::string OptionPurpose(const CLI::Option* opt) {
  return opt == nullptr ? "" : Summary(opt->get_description());
}

// Every value typed for `opt` ("--speed 20 --speed 1", "--speed=1").
std::vector<std::string> TypedValues(const CLI::Option& opt, const std::vector<std::string>& args) {
  std::vector<std::string> names;
  for (const std::string& l : opt.get_lnames()) names.push_back("--" + l);
  for (const std::string& s : opt.get_snames()) names.push_back("-" + s);
  std::vector<std::string> values;
  for (size_t i = 0; i < args.size(); ++i)
    for (const std::string& name : names) {
      if (args[i] == name) values.push_back(i + 1 < args.size() ? args[i + 1] : "");
      else if (args[i].rfind(name + "=", 0) == 0) values.push_back(args[i].substr(name.size() + 1));
    }
  return values;
}

std::string QuotedWord(const std::string& text) { return "'" + text + "'"; }

// "10.000000" (CLI11's bound of a range) as "10".
std::string ShortNumber(std::string number) {
  if (number.find('.') == std::string::npos) return number;
  while (!number.empty() && number.back() == '0') number.pop_back();
  if (!number.empty() && number.back() == '.') number.pop_back();
  return number;
}

std::string CountWords(size_t n) {
  return n == 1 ? "once" : n == 2 ? "twice" : fmt::format("{} times", n);
}

// An option given more values than it takes: given twice, or too many values at once.
std::string TooMany(const CLI::Option* opt, const std::string& name, const std::string& most,
                    const std::vector<std::string>& args) {
  const std::vector<std::string> values = opt ? TypedValues(*opt, args) : std::vector<std::string>{};
  if (values.size() > 1) {
    std::vector<std::string> quoted;
    for (const std::string& v : values) quoted.push_back(v);
    return fmt::format("{} is given {} ({}): give it once", name, CountWords(values.size()),
                       JoinWords(quoted, " and "));
  }
  return most == "1" ? fmt::format("{} takes one value", name)
                     : fmt::format("{} takes at most {} values", name, most);
}

std::string MissingArgument(const CLI::App& command, const CLI::Option* opt, const std::string& name) {
  const std::string purpose = OptionPurpose(opt);
  const std::string what = opt != nullptr && !opt->nonpositional() ? "its " + name : name;
  std::string message = fmt::format("{} needs {}", CommandPath(command), what);
  if (!purpose.empty()) message += ": " + purpose;
  if (opt != nullptr && ValueWords(opt).rfind("one of", 0) == 0) message += " (" + ValueWords(opt) + ")";
  return message;
}

std::string NotExpected(const CLI::App& command, std::string_view listed) {
  std::vector<std::string> words = SplitAt(listed, ' ');
  std::reverse(words.begin(), words.end());  // CLI11 lists them last first
  std::vector<std::string> options;
  std::vector<std::string> others;
  for (const std::string& w : words) (w.rfind('-', 0) == 0 && w.size() > 1 ? options : others).push_back(QuotedWord(w));
  const std::string path = CommandPath(command);
  std::vector<std::string> parts;
  if (!options.empty())
    parts.push_back(fmt::format("{} has no option {}", path, JoinWords(options, " or ")));
  if (!others.empty()) {
    if (command.get_parent() == nullptr && !VisibleCommands(command).empty())
      parts.push_back(fmt::format("{} is not a command of {}", JoinWords(others, " or "), path));
    else
      parts.push_back(fmt::format("{} does not take {}", path, JoinWords(others, " or ")));
  }
  return JoinWords(parts, "; ");
}

// A validator's refusal ("--format: xml not in {text,json}"): CLI11's own texts in our words;
// our validators' (cli_checks.h) already are.
std::string RefusedValue(const CLI::Option* opt, const std::string& name, const std::string& why) {
  if (auto p = MatchPieces(why, {"", " not in {", "}"}))
    return fmt::format("{}: {} is not {}", name, QuotedWord((*p)[0]), ValueWords(opt));
  if (auto p = MatchPieces(why, {"Value ", " not in range ", " to ", ""}))
    return fmt::format("{}: {} is not between {} and {}", name, (*p)[0], ShortNumber((*p)[1]),
                       ShortNumber((*p)[2]));
  if (auto p = MatchPieces(why, {"File does not exist: ", ""})) return "no such file: " + (*p)[0];
  if (auto p = MatchPieces(why, {"Directory does not exist: ", ""})) return "no such directory: " + (*p)[0];
  if (auto p = MatchPieces(why, {"Failed parsing ", " as a ", ""}))
    return fmt::format("{}: {} is not {}", name, QuotedWord((*p)[0]), ValueWords(opt));
  return fmt::format("{}: {}", name, why);
}

}  // namespace

std::string PlainUsageMessage(const CLI::App& app, const CLI::ParseError& e,
                              const std::vector<std::string>& args) {
  const std::string kind = e.get_name();
  const std::string what = e.what();
  const CLI::App& command = ActiveCommand(app);
  const auto option = [&](const std::string& name) { return NamedOption(command, name); };
  // CLI11 names an ExtrasError after the command, not the error: known by its text alone.
  if (auto p = MatchPieces(what, {"The following argument was not expected: ", ""})) return NotExpected(command, (*p)[0]);
  if (auto p = MatchPieces(what, {"The following arguments were not expected: ", ""})) return NotExpected(command, (*p)[0]);
  if (kind == "ArgumentMismatch") {
    if (auto p = MatchPieces(what, {"", ": At Most ", " required but received ", ""}))
      return TooMany(option((*p)[0]), (*p)[0], (*p)[1], args);
    if (auto p = MatchPieces(what, {"", ": At least ", " required but received ", ""}))
      return fmt::format("{} needs at least {} values, not {}", (*p)[0], (*p)[1], (*p)[2]);
    if (auto p = MatchPieces(what, {"", ": ", " required ", " missing"}))
      return fmt::format("{} needs {} after it", (*p)[0], ValueWords(option((*p)[0])));
    if (auto p = MatchPieces(what, {"Expected exactly ", " arguments to ", ", got ", ""}))
      return fmt::format("{} takes {} values, not {}", (*p)[1], (*p)[0], (*p)[2]);
    if (auto p = MatchPieces(what, {"Expected at least ", " arguments to ", ", got ", ""}))
      return fmt::format("{} needs at least {} values, not {}", (*p)[1], (*p)[0], (*p)[2]);
    if (auto p = MatchPieces(what, {"", " was given a disallowed flag override"}))
      return fmt::format("{} is a switch: it takes no value", (*p)[0]);
  } else if (kind == "RequiredError") {
    if (what == "A subcommand is required")
      return fmt::format("{} needs a command ({} --help lists them)", CommandPath(command), CommandPath(command));
    if (auto p = MatchPieces(what, {"", " is required"})) return MissingArgument(command, option((*p)[0]), (*p)[0]);
  } else if (kind == "ConversionError") {
    if (auto p = MatchPieces(what, {"Could not convert: ", " = ", ""})) {
      const CLI::Option* opt = option((*p)[0]);
      if (opt != nullptr && opt->get_expected_max() == 0)
        return fmt::format("{} is a switch: it takes no value (or true/false)", (*p)[0]);
      return fmt::format("{}: {} is not {}", (*p)[0], QuotedWord((*p)[1]), ValueWords(opt));
    }
    if (auto p = MatchPieces(what, {"The value ", " is not an allowed value for ", ""}))
      return fmt::format("{}: {} is not allowed", (*p)[1], QuotedWord((*p)[0]));
    if (auto p = MatchPieces(what, {"", ": too many inputs for a flag"}))
      return fmt::format("{} is a switch: it takes no value", (*p)[0]);
    if (auto p = MatchPieces(what, {"", ": Should be true/false or a number"}))
      return fmt::format("{} is a switch: it takes no value (or true/false)", (*p)[0]);
  } else if (kind == "ValidationError") {
    if (auto p = MatchPieces(what, {"", ": ", ""})) return RefusedValue(option((*p)[0]), (*p)[0], (*p)[1]);
  } else if (kind == "ExcludesError") {
    if (auto p = MatchPieces(what, {"", " excludes ", ""}))
      return fmt::format("{} and {} cannot be given together", (*p)[0], (*p)[1]);
  } else if (kind == "RequiresError") {
    if (auto p = MatchPieces(what, {"", " requires ", ""}))
      return fmt::format("{} needs {} too", (*p)[0], (*p)[1]);
  }
  return what;
}

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
  const std::string message = DisplayLines(PlainUsageMessage(app, e, args));
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
