// Checks on command-line values whose refusal reads plainly: a bound named as a number a person
// reads ("must be 0 or more", never CLI11's "not in range 0 to 1.797...e308"), and an input file
// that must exist, refused as bad input (accelcal::Error, exit 1) like every other unreadable
// file, not as a usage error (usage_errors.h).
#pragma once

#include <string>

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

}  // namespace accelcal::cli
