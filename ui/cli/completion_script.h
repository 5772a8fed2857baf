// Bash completion for `accelcal`, written from the command line's own definition: the commands,
// their options and positionals, and what each takes. A command or option added later is
// completed without an edit here; what a value is comes from the option itself:
//   a flag                          nothing (the next word is not its value)
//   a set of choices (IsMember)     the choices
//   a shipped procedure / scenario  the shipped names (asked of the program) and *.toml files
//     (ShippedFile, shipped_files.h)
//   a name with "source"            sim, -, file:PATH, serial: with the serial ports present
//                                   (/dev/ttyUSB*, /dev/ttyACM*), tcp:, ... (the forms
//                                   ParseSourceSpec names)
//   "session"                       session files (*.db) and directories
//   a name ending in "dir"          directories
//   a number, or free text (device, date, place, ...)   nothing
//   anything else                   files
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace accelcal::cli {

enum class ValueKind { kFlag, kNone, kFile, kDirectory, kSession, kProcedure, kScenario, kSource, kChoices };

struct ValueSpec {
  ValueKind kind = ValueKind::kFile;
  std::vector<std::string> choices;  // kChoices
};

// What `option` takes, by the rules above.
ValueSpec ValueSpecOf(const CLI::Option& option);

// The forms of --source ("sim", "file:PATH", "serial:DEVICE@BAUD", ...), as the source parser
// names them in its refusal of an unknown source.
std::vector<std::string> SourceForms();

// The completion script (bash), for a program named `program` ("accelcal").
std::string BashCompletionScript(const CLI::App& root, std::string_view program);

}  // namespace accelcal::cli
