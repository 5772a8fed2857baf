#include "cli/shipped_files.h"

#include <algorithm>
#include <system_error>

#include <fmt/core.h>

#include "accelcal/base/error.h"

// Set by CMakeLists.txt for this library: the installed data directory relative to the installed
// program (GNUInstallDirs' bindir -> datadir/accelcal), the build tree, and the source tree.
#ifndef ACCELCAL_DATA_FROM_BIN
#error "ACCELCAL_DATA_FROM_BIN is set by CMakeLists.txt"
#endif

namespace accelcal::cli {
namespace fs = std::filesystem;
namespace {

fs::path ExecutableDir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

// `dir` is `root` or below it (both made canonical as far as they exist).
bool IsWithin(const fs::path& dir, const fs::path& root) {
  std::error_code ec;
  const fs::path d = fs::weakly_canonical(dir, ec);
  if (ec) return false;
  const fs::path r = fs::weakly_canonical(root, ec);
  if (ec) return false;
  const auto [r_end, d_at] = std::mismatch(r.begin(), r.end(), d.begin(), d.end());
  return r_end == r.end();
}

bool IsRegularFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

// Shipped files renamed since they were first shipped: a script, a shell's history or a
// session's notes that name the old file (by name or by its path in the source tree) still find
// the new one.
struct RenamedShipped {
  std::string_view kind;
  std::string_view old_name;
  std::string_view new_name;
};
constexpr RenamedShipped kRenamedShipped[] = {
    {kShippedProcedures, "seed_calibration.toml", "full_calibration.toml"},
};

// The shipped name `typed` now has when its file name (".toml" added when missing) is a
// renamed one's old name; empty otherwise.
std::string_view RenamedTo(std::string_view kind, const std::string& typed) {
  const std::string name = fs::path(typed).filename().string();
  for (const RenamedShipped& r : kRenamedShipped)
    if (r.kind == kind && (name == r.old_name || name + ".toml" == r.old_name)) return r.new_name;
  return {};
}

}  // namespace

fs::path ShippedDirFrom(const fs::path& exe_dir, std::string_view kind) {
  std::error_code ec;
  const fs::path installed = (exe_dir / ACCELCAL_DATA_FROM_BIN / kind).lexically_normal();
  if (fs::is_directory(installed, ec)) return installed;
  if (IsWithin(exe_dir, ACCELCAL_BUILD_DIR)) return fs::path(ACCELCAL_SOURCE_DATA_DIR) / kind;
  return {};
}

fs::path ShippedDir(std::string_view kind) {
  const fs::path exe_dir = ExecutableDir();
  const fs::path dir = ShippedDirFrom(exe_dir, kind);
  if (dir.empty())
    throw Error(fmt::format(
        "cannot find the {} installed with accelcal: looked in {}; reinstall accelcal, or name "
        "the file by its path",
        kind, (exe_dir / ACCELCAL_DATA_FROM_BIN / kind).lexically_normal().string()));
  return dir;
}

std::vector<std::string> ShippedNames(std::string_view kind) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(ShippedDir(kind), ec))
    if (e.path().extension() == ".toml" && IsRegularFile(e.path())) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string ResolveShipped(std::string_view kind, const std::string& typed) {
  std::error_code ec;
  if (typed.empty() || fs::exists(typed, ec)) return typed;
  if (const std::string_view renamed = RenamedTo(kind, typed); !renamed.empty()) {
    try {
      if (const fs::path now = ShippedDir(kind) / renamed; IsRegularFile(now)) return now.string();
    } catch (const Error&) {
      return typed;  // nothing shipped to look in: the reader says the file is not there
    }
  }
  if (typed.find('/') != std::string::npos) return typed;
  fs::path dir;
  try {
    dir = ShippedDir(kind);
  } catch (const Error&) {
    return typed;  // nothing shipped to look in: the reader says the file is not there
  }
  for (const std::string& name : {typed, typed + ".toml"})
    if (IsRegularFile(dir / name)) return (dir / name).string();
  return typed;
}

std::string ShippedValidatorName(std::string_view kind) { return fmt::format("shipped {}", kind); }

CLI::Validator ShippedFile(std::string_view kind) {
  return CLI::Validator(
      [kind = std::string(kind)](std::string& value) {
        value = ResolveShipped(kind, value);
        return std::string();
      },
      "", ShippedValidatorName(kind));
}

}  // namespace accelcal::cli
