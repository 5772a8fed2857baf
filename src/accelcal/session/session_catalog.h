// Listing the sessions of a directory, optionally filtered (by device serial, by procedure).
// Sessions are read read-only (no lock), so listing works while a wizard writes one.
#pragma once

#include <string>
#include <vector>

#include "accelcal/session/session_store.h"

namespace accelcal {

// Empty fields match every session.
struct SessionFilter {
  std::string device;     // SessionInfo::device, exactly
  std::string procedure;  // SessionInfo::procedure, exactly
};

// The *.db files of `dir`, sorted by name (= by creation time for default names). Throws
// accelcal::Error when `dir` is not a directory.
std::vector<std::string> SessionFilesIn(const std::string& dir);

// The sessions of `dir` that match `filter`, sorted by creation time (then name). A file that
// cannot be read as a session is skipped; its path and reason go to `*unreadable` when given.
std::vector<SessionInfo> ListSessions(const std::string& dir, const SessionFilter& filter,
                                      std::vector<std::string>* unreadable = nullptr);

}  // namespace accelcal
