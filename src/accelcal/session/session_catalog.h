// The sessions in a directory: the `*.db` files opened read-only (no lock, so it works while a
// wizard writes), optionally filtered by device serial and procedure title, sorted by creation
// time. For `accelcal sessions`, `accelcal noise` and a device's history.
#pragma once

#include <string>
#include <vector>

#include "accelcal/session/session_store.h"

namespace accelcal {

struct SessionFilter {
  std::string device;     // the session's device serial must equal this; empty = any
  std::string procedure;  // the session's procedure (its title) must equal this; empty = any
};

// A file that looked like a session but could not be read as one.
struct UnreadableSession {
  std::string path;
  std::string reason;
};

struct SessionListing {
  std::vector<SessionInfo> sessions;  // matching the filter, by created_utc then name
  std::vector<UnreadableSession> unreadable;  // by path
};

// The `*.db` regular files of `dir`, sorted by name (= by creation time for default names).
// Throws accelcal::Error when `dir` is not a readable directory.
std::vector<std::string> SessionFilesIn(const std::string& dir);

// The sessions of `dir` matching `filter`. Throws accelcal::Error when `dir` is not a readable
// directory; a file that cannot be opened as a session is listed in `unreadable`, not thrown.
SessionListing ListSessions(const std::string& dir, const SessionFilter& filter = {});

}  // namespace accelcal
