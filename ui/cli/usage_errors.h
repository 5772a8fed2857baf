// How `accelcal` reports a command line it cannot take (CLI11's parse errors), in the one form of
// every error: "accelcal: error: <what>" on stderr, with a "did you mean --session?" for a
// mistyped option or subcommand, then where the usage is. Exit codes (docs/guide.md, "Using it": exit status):
// 0 done (and --help, --version), 1 the job failed or its input was refused (a file missing or
// unreadable, a refused value, a source that is not there), 2 the command line itself is wrong.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace accelcal::cli {

inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

// The known name nearest `typed` ("--sesion" -> "--session"), within two edits (one for names of
// up to four letters); empty when none is that near.
std::string NearestName(std::string_view typed, const std::vector<std::string>& known);

// The long options and subcommand names `app` and its parsed subcommands know ("--session",
// "fit"), for NearestName.
std::vector<std::string> KnownNames(const CLI::App& app);

// CLI11's message for `e` in our words: the option or argument as typed, what it takes and what
// was wrong ("--speed is given twice (20 and 1): give it once", "--speed needs a number after
// it", "accelcal simulate needs its scenario: ..."), for every parse error CLI11 raises at a
// command line; a message already in our words (our validators') is kept.
std::string PlainUsageMessage(const CLI::App& app, const CLI::ParseError& e,
                              const std::vector<std::string>& args);

// Prints `e` as above (help and version as CLI11 prints them) and returns the exit status: 0 for
// help and version, kExitUsage otherwise.
int ReportParseError(const CLI::App& app, const CLI::ParseError& e, const std::vector<std::string>& args);

}  // namespace accelcal::cli
