// The files shipped with the program (procedures/*.toml, scenarios/*.toml): where they are, and
// a procedure or scenario named by its shipped name ("noise.toml", "noise", "clumsy_bump").
//
// Installed (cmake --install, the .deb), they sit in share/accelcal/ beside the program's bin/
// (../share/accelcal from the executable, whatever the prefix or root it was installed under).
// A program run from its build tree takes them from the source tree instead, as before install
// existed. The executable's own location decides, never the working directory.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace accelcal::cli {

// The kinds of shipped files: their directory's name.
inline constexpr std::string_view kShippedProcedures = "procedures";
inline constexpr std::string_view kShippedScenarios = "scenarios";

// The directory of the shipped `kind` ("procedures"). Throws accelcal::Error naming where it
// looked when there is none (a program copied away from its share/ directory).
std::filesystem::path ShippedDir(std::string_view kind);

// The .toml files of ShippedDir(kind), by name, sorted.
std::vector<std::string> ShippedNames(std::string_view kind);

// `typed` as the path to open: itself when it names an existing file; else, when its file name is
// the old name of a renamed shipped file (seed_calibration.toml, now full_calibration.toml),
// that file as shipped now, whatever directory `typed` named; else itself when it holds a '/';
// else the shipped file of that name (".toml" added when missing) when there is one; else
// itself, for the reader to refuse ("no such file").
std::string ResolveShipped(std::string_view kind, const std::string& typed);

// A CLI11 transform applying ResolveShipped to an option's value. Its name (ShippedValidatorName)
// tells the completion what the option takes; it adds nothing to --help.
CLI::Validator ShippedFile(std::string_view kind);
std::string ShippedValidatorName(std::string_view kind);

// Where the executable's directory finds its shipped files, relative to it, and whether it is in
// the build tree; exposed for the tests. `exe_dir` absolute.
std::filesystem::path ShippedDirFrom(const std::filesystem::path& exe_dir, std::string_view kind);

}  // namespace accelcal::cli
