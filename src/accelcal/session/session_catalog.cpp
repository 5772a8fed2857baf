#include "accelcal/session/session_catalog.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "accelcal/error.h"

namespace accelcal {

namespace fs = std::filesystem;

std::vector<std::string> SessionFilesIn(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw Error(fmt::format("no session directory {}", dir));
  std::vector<std::string> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".db") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<SessionInfo> ListSessions(const std::string& dir, const SessionFilter& filter,
                                      std::vector<std::string>* unreadable) {
  SessionOpenOptions read_only;
  read_only.read_only = true;
  std::vector<SessionInfo> sessions;
  for (const std::string& path : SessionFilesIn(dir)) {
    try {
      SessionInfo info = SessionStore::Open(path, read_only)->Info();
      if (!filter.device.empty() && info.device != filter.device) continue;
      if (!filter.procedure.empty() && info.procedure != filter.procedure) continue;
      sessions.push_back(std::move(info));
    } catch (const Error& e) {
      if (unreadable != nullptr) unreadable->push_back(fmt::format("{}: {}", path, e.what()));
    }
  }
  std::stable_sort(sessions.begin(), sessions.end(), [](const SessionInfo& a, const SessionInfo& b) {
    return a.created_utc != b.created_utc ? a.created_utc < b.created_utc : a.name < b.name;
  });
  return sessions;
}

}  // namespace accelcal
