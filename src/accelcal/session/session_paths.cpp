#include "accelcal/session/session_paths.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/base/utc_time.h"

namespace accelcal {

namespace fs = std::filesystem;

std::string DefaultSessionDir() {
  const char* xdg = std::getenv("XDG_DATA_HOME");
  // The XDG spec: a relative XDG_DATA_HOME is invalid and must be ignored.
  if (xdg && *xdg && fs::path(xdg).is_absolute()) return (fs::path(xdg) / "accelcal" / "sessions").string();
  const char* home = std::getenv("HOME");
  if (!home || !*home) throw Error("cannot find the session directory: neither XDG_DATA_HOME nor HOME is set");
  return (fs::path(home) / ".local" / "share" / "accelcal" / "sessions").string();
}

std::string NewSessionPath() {
  const fs::path dir = DefaultSessionDir();
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error(fmt::format("cannot create the session directory {}: {}", dir.string(), ec.message()));
  const std::string stem = UtcNowCompact();
  fs::path path = dir / (stem + ".db");
  for (int i = 2; fs::exists(path); ++i) path = dir / fmt::format("{}-{}.db", stem, i);
  return path.string();
}

std::string ResolveSessionPath(const std::string& path_or_name) {
  if (fs::is_regular_file(path_or_name)) return path_or_name;
  // A bare name looks in the default directory; anything with a slash was meant as a path.
  if (path_or_name.find('/') == std::string::npos) {
    const fs::path dir = DefaultSessionDir();
    for (const std::string& candidate : {path_or_name, path_or_name + ".db"})
      if (fs::is_regular_file(dir / candidate)) return (dir / candidate).string();
    throw Error(fmt::format("no session {} (looked in {} and the current directory)", path_or_name,
                            dir.string()));
  }
  throw Error(fmt::format("no session {}", path_or_name));
}

}  // namespace accelcal
