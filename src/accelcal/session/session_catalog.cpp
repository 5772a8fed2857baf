#include "accelcal/session/session_catalog.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal {

namespace fs = std::filesystem;

std::vector<std::string> SessionFilesIn(const std::string& dir) {
  std::error_code ec;
  fs::directory_iterator it(dir, ec);
  if (ec) throw Error(fmt::format("cannot list sessions in {}: {}", dir, ec.message()));
  std::vector<std::string> files;
  for (const fs::directory_entry& entry : it) {
    if (entry.is_regular_file(ec) && entry.path().extension() == ".db")
      files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

SessionListing ListSessions(const std::string& dir, const SessionFilter& filter) {
  SessionListing listing;
  SessionOpenOptions read_only;
  read_only.read_only = true;
  for (const std::string& path : SessionFilesIn(dir)) {
    SessionInfo info;
    try {
      info = SessionStore::Open(path, read_only)->Info();
    } catch (const Error& e) {
      listing.unreadable.push_back({path, e.what()});
      continue;
    }
    if (!filter.device.empty() && info.device != filter.device) continue;
    if (!filter.procedure.empty() && info.procedure != filter.procedure) continue;
    listing.sessions.push_back(std::move(info));
  }
  std::stable_sort(listing.sessions.begin(), listing.sessions.end(),
                   [](const SessionInfo& a, const SessionInfo& b) {
                     return a.created_utc != b.created_utc ? a.created_utc < b.created_utc
                                                           : a.name < b.name;
                   });
  return listing;
}

}  // namespace accelcal
