#include "cli/completion_script.h"

#include <algorithm>
#include <array>

#include <fmt/core.h>

#include "accelcal/acquire/source/source_spec.h"
#include "accelcal/base/error.h"
#include "cli/cli_checks.h"
#include "cli/man_page.h"
#include "cli/shipped_files.h"

namespace accelcal::cli {
namespace {

// Options whose value is free text a person types: nothing to complete.
constexpr std::array kFreeText{"device", "date", "place", "rostopic", "columns", "operator", "gravity"};

// The option's own name without dashes: its first long name, else short, else positional.
std::string BareName(const CLI::Option& option) {
  if (!option.get_lnames().empty()) return option.get_lnames().front();
  if (!option.get_snames().empty()) return option.get_snames().front();
  return option.get_name(true, false);
}

bool HasValidator(const CLI::Option& option, const std::string& name) {
  // CLI11 looks validators up only through a non-const accessor; the lookup changes nothing.
  try {
    const_cast<CLI::Option&>(option).get_validator(name);
    return true;
  } catch (const CLI::OptionNotFound&) {
    return false;
  }
}

bool IsNumberType(const std::string& type_name) {
  const std::string base = type_name.substr(0, type_name.find(':'));
  for (const char* number : {"INT", "UINT", "FLOAT", "NUMBER", "BOOLEAN", "CHAR"})
    if (base == number) return true;
  return false;
}

bool NameEndsWith(const std::string& text, std::string_view end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

std::string KindWord(const ValueSpec& spec) {
  switch (spec.kind) {
    case ValueKind::kFlag: return "flag";
    case ValueKind::kNone: return "none";
    case ValueKind::kFile: return "file";
    case ValueKind::kDirectory: return "dir";
    case ValueKind::kSession: return "session";
    case ValueKind::kProcedure: return "procedure";
    case ValueKind::kScenario: return "scenario";
    case ValueKind::kSource: return "source";
    case ValueKind::kChoices: break;
  }
  std::string words = "choices";
  for (const std::string& c : spec.choices) words += " " + c;
  return words;
}

// `text` in single quotes for bash.
std::string BashQuoted(std::string_view text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string JoinSpaced(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

void SpecLine(std::string& out, const std::string& key, const std::string& reply) {
  if (!reply.empty()) out += fmt::format("    {}) REPLY={} ;;\n", BashQuoted(key), BashQuoted(reply));
}

// The case lines of one command (path "" is the program itself) and of its subcommands.
void SpecLines(std::string& out, const CLI::App& app, const std::string& path) {
  std::vector<std::string> commands;
  for (const CLI::App* sub : VisibleCommands(app)) commands.push_back(sub->get_name());
  SpecLine(out, "commands:" + path, JoinSpaced(commands));
  std::vector<std::string> names;
  std::vector<std::string> positionals;
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->get_group().empty()) continue;  // hidden
    const std::string kind = KindWord(ValueSpecOf(*opt));
    if (opt->get_positional() && !opt->nonpositional()) {
      positionals.push_back(kind.substr(0, kind.find(' ')) == "choices" ? "none" : kind);
      if (opt->get_expected_max() > 1) positionals.back() += "...";
      continue;
    }
    for (const std::string& s : opt->get_snames()) names.push_back("-" + s);
    for (const std::string& l : opt->get_lnames()) names.push_back("--" + l);
  }
  SpecLine(out, "options:" + path, JoinSpaced(names));
  SpecLine(out, "positionals:" + path, JoinSpaced(positionals));
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->get_group().empty() || !opt->nonpositional()) continue;
    const std::string kind = KindWord(ValueSpecOf(*opt));
    for (const std::string& s : opt->get_snames()) SpecLine(out, "value:" + path + ":-" + s, kind);
    for (const std::string& l : opt->get_lnames()) SpecLine(out, "value:" + path + ":--" + l, kind);
  }
  for (const CLI::App* sub : VisibleCommands(app))
    SpecLines(out, *sub, path.empty() ? sub->get_name() : path + " " + sub->get_name());
}

// The part of the script that does not depend on the commands: finding the command and the
// word under the cursor, and the values of each kind.
constexpr const char* kScriptBody = R"BASH(
# _accelcal_values PROGRAM KIND VALUE: the completions of VALUE, a value of KIND, in
# _accelcal_cands.
_accelcal_values() {
  local prog=$1 kind=$2 value=$3 w
  _accelcal_cands=()
  case $kind in
    choices\ *)
      for w in ${kind#choices }; do [[ $w == "$value"* ]] && _accelcal_cands+=("$w"); done ;;
    file)
      mapfile -t _accelcal_cands < <(compgen -f -- "$value") ;;
    dir)
      mapfile -t _accelcal_cands < <(compgen -d -- "$value") ;;
    session)
      mapfile -t _accelcal_cands < <(compgen -d -- "$value"; compgen -f -X '!*.db' -- "$value") ;;
    procedure|scenario)
      # The shipped ones by name (the program says where it finds them), then *.toml files.
      for w in $("$prog" help-shipped "${kind}s" 2>/dev/null); do
        [[ $w == "$value"* ]] && _accelcal_cands+=("$w")
      done
      mapfile -t -O "${#_accelcal_cands[@]}" _accelcal_cands \
        < <(compgen -d -- "$value"; compgen -f -X '!*.toml' -- "$value") ;;
    source)
      _accelcal_sources "$value" ;;
  esac
}

# _accelcal_sources VALUE: the source forms (sim, -, file:PATH, serial:DEVICE@BAUD, ...); a
# DEVICE is one of the serial ports present, a PATH a file. ACCELCAL_COMPLETION_DEV replaces
# /dev (for the tests).
_accelcal_sources() {
  local value=$1 dev=${ACCELCAL_COMPLETION_DEV:-/dev} form scheme arg port baud
  local -a ports=() found=()
  for port in "$dev"/ttyUSB* "$dev"/ttyACM*; do [[ -e $port ]] && ports+=("$port"); done
  _accelcal_spec sources
  for form in $REPLY; do
    if [[ $form != *:* ]]; then found+=("$form"); continue; fi
    scheme=${form%%:*}:
    if [[ $value != "$scheme"* ]]; then
      found+=("$scheme")
      [[ $form == *DEVICE* ]] && for port in "${ports[@]}"; do found+=("$scheme$port@"); done
      continue
    fi
    arg=${value#"$scheme"}
    case $form in
      *DEVICE*@*)
        if [[ $arg == *@* ]]; then
          for baud in 9600 19200 38400 57600 115200 230400 460800 921600; do
            found+=("$scheme${arg%@*}@$baud")
          done
        else
          for port in "${ports[@]}"; do found+=("$scheme$port@"); done
        fi ;;
      *PATH*)
        while IFS= read -r w; do found+=("$scheme$w"); done < <(compgen -f -- "$arg") ;;
    esac
  done
  for w in "${found[@]}"; do [[ $w == "$value"* ]] && _accelcal_cands+=("$w"); done
}

_accelcal() {
  local line=${COMP_LINE:0:COMP_POINT}
  local -a words
  read -ra words <<< "$line"
  [[ -z $line || $line == *[[:space:]] ]] && words+=('')
  local cur=${words[${#words[@]}-1]} prog=${words[0]/#\~/$HOME}
  local path='' option='' npos=0 i w
  # The command (and subcommand) named so far, the option waiting for its value, and how many
  # positionals the command has been given.
  for ((i = 1; i < ${#words[@]} - 1; i++)); do
    w=${words[i]}
    if [[ -n $option ]]; then option=''; continue; fi
    case $w in
      --|--*=*) ;;
      -*)
        _accelcal_spec "value:$path:$w"
        [[ -n $REPLY && $REPLY != flag ]] && option=$w ;;
      *)
        _accelcal_spec "commands:$path"
        if [[ " $REPLY " == *" $w "* ]]; then path=${path:+$path }$w; npos=0; else npos=$((npos + 1)); fi ;;
    esac
  done

  local value=$cur prefix='' kind=''
  local -a cands=()
  if [[ -n $option ]]; then
    _accelcal_spec "value:$path:$option"; kind=$REPLY
  elif [[ $cur == --*=* ]]; then
    prefix=${cur%%=*}=; value=${cur#*=}
    _accelcal_spec "value:$path:${cur%%=*}"; kind=$REPLY
  elif [[ $cur == -* ]]; then
    _accelcal_spec "options:$path"; kind="choices $REPLY"
  else
    _accelcal_spec "commands:$path"
    [[ -n $REPLY ]] && for w in $REPLY; do [[ $w == "$cur"* ]] && cands+=("$w"); done
    _accelcal_spec "positionals:$path"
    local -a kinds=($REPLY)
    if ((npos < ${#kinds[@]})); then
      kind=${kinds[npos]%...}
    elif ((${#kinds[@]} > 0)) && [[ ${kinds[-1]} == *... ]]; then
      kind=${kinds[-1]%...}
    fi
  fi
  case $kind in
    file|dir|session|procedure|scenario) compopt -o filenames 2>/dev/null ;;
  esac
  _accelcal_values "$prog" "$kind" "$value"
  for w in "${_accelcal_cands[@]}"; do cands+=("$prefix$w"); done
  # A source form waiting for the rest of it (serial:, serial:/dev/ttyUSB0@) takes no space.
  if ((${#cands[@]} == 1)) && [[ ${cands[0]} == *[:@] ]]; then compopt -o nospace 2>/dev/null; fi
  # Bash replaces only what follows the last word-break character (':' and '=' by default).
  local breaks='' cut=''
  [[ $COMP_WORDBREAKS == *:* ]] && breaks+=':'
  [[ $COMP_WORDBREAKS == *=* ]] && breaks+='='
  [[ -n $breaks && $cur == *[$breaks]* ]] && cut=${cur%"${cur##*[$breaks]}"}
  COMPREPLY=()
  for w in "${cands[@]}"; do COMPREPLY+=("${w#"$cut"}"); done
}
)BASH";

}  // namespace

ValueSpec ValueSpecOf(const CLI::Option& option) {
  if (option.nonpositional() && option.get_expected_max() == 0) return {ValueKind::kFlag, {}};
  if (HasValidator(option, ShippedValidatorName(kShippedProcedures))) return {ValueKind::kProcedure, {}};
  if (HasValidator(option, ShippedValidatorName(kShippedScenarios))) return {ValueKind::kScenario, {}};
  const std::string type_name = option.get_type_name();
  if (std::vector<std::string> choices = OptionChoices(option); !choices.empty())
    return {ValueKind::kChoices, std::move(choices)};
  const std::string name = BareName(option);
  if (name.find("source") != std::string::npos) return {ValueKind::kSource, {}};
  if (name == "session") return {ValueKind::kSession, {}};
  if (NameEndsWith(name, "dir")) return {ValueKind::kDirectory, {}};
  if (IsNumberType(type_name)) return {ValueKind::kNone, {}};
  if (std::find(kFreeText.begin(), kFreeText.end(), name) != kFreeText.end()) return {ValueKind::kNone, {}};
  return {ValueKind::kFile, {}};
}

std::vector<std::string> SourceForms() {
  std::string message;
  try {
    ParseSourceSpec("");
  } catch (const Error& e) {
    message = e.what();
  }
  // "unknown source '': expected sim, file:PATH, serial:DEVICE@BAUD, tcp:HOST:PORT or -"
  const size_t start = message.find("expected ");
  std::vector<std::string> forms;
  if (start == std::string::npos) return forms;
  std::string list = message.substr(start + 9);
  for (size_t or_at; (or_at = list.find(" or ")) != std::string::npos;) list.replace(or_at, 4, ",");
  for (const std::string& form : SplitAt(list, ','))
    if (const size_t first = form.find_first_not_of(' '); first != std::string::npos) forms.push_back(form.substr(first));
  return forms;
}

std::string BashCompletionScript(const CLI::App& root, std::string_view program) {
  std::string spec;
  SpecLines(spec, root, "");
  SpecLine(spec, "sources", JoinSpaced(SourceForms()));
  return fmt::format(
      "# bash completion for {0}: commands, options, sources, procedures, scenarios, sessions.\n"
      "# Written by `{0} help-completion` from the program's own command line: do not edit (the\n"
      "# build writes it again). Installed as share/bash-completion/completions/{0}.\n"
      "\n"
      "# _accelcal_spec KEY: REPLY, what the command line defines for KEY:\n"
      "#   commands:PATH        the subcommands of PATH ('' the program, 'wizard' a command)\n"
      "#   options:PATH         its options\n"
      "#   value:PATH:OPTION    what OPTION takes: flag, none, file, dir, session, procedure,\n"
      "#                        scenario, source or 'choices A B ...'\n"
      "#   positionals:PATH     what its positionals take, in order (KIND... repeats)\n"
      "#   sources              the forms of a source\n"
      "_accelcal_spec() {{\n"
      "  case $1 in\n"
      "{1}"
      "    *) REPLY='' ;;\n"
      "  esac\n"
      "}}\n"
      "{2}\n"
      "complete -F _accelcal {0}\n",
      program, spec, kScriptBody);
}

}  // namespace accelcal::cli
