// Checks on command-line values whose refusal reads plainly: a bound named as a number a person
// reads ("must be 0 or more", never CLI11's "not in range 0 to 1.797...e308"), and an input file
// that must exist, refused as bad input (accelcal::Error, exit 1) like every other unreadable
// file, not as a usage error (usage_errors.h).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace accelcal::cli {

// A number >= 0 ("must be 0 or more, not -1").
CLI::Validator NonNegative();
// A number > 0 ("must be more than 0, not 0").
CLI::Validator Positive();
// A file that exists. Throws accelcal::Error ("no such file: missing.csv") while parsing: CLI11
// lets any exception other than its ValidationError pass through its validators, so main
// reports it as bad input.
CLI::Validator InputFile();
// As InputFile, or a ROS 2 bag folder (a directory holding metadata.yaml).
CLI::Validator InputFileOrBag();

// The values an IsMember check of `option` allows, as --help shows them in its type
// ("TEXT:{text,json}" -> text, json); empty without one.
std::vector<std::string> OptionChoices(const CLI::Option& option);

// `text` cut at each `separator`, empty pieces left out: "a,,b" -> a, b.
std::vector<std::string> SplitAt(std::string_view text, char separator);

// Every option of `app` and its subcommands that holds an unsigned number refuses a negative one
// ("must be a whole number, 0 or more, not -3"): CLI11 reads "-3" into an unsigned as 2^64 - 3,
// silently. Call once every command is set up.
void RefuseNegativeWholeNumbers(CLI::App& app);

}  // namespace accelcal::cli
