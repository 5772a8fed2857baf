// What the subcommands share at their edge: where their output text goes, and where the shipped
// procedures are.
#pragma once

#include <string>

namespace accelcal::cli {

// `text` to the file at `path`, written atomically (a crash never leaves half a file), or to
// standard output when `path` is empty. Throws accelcal::Error naming the file.
void WriteOutputText(const std::string& path, const std::string& text);

// A procedure shipped with the program ("full_calibration.toml", "noise.toml"): installed in
// share/accelcal/procedures, or the source tree's for a program run from its build (shipped_files.h).
std::string ShippedProcedurePath(const std::string& file_name);

}  // namespace accelcal::cli
