// The one-writer lock of a session: an exclusive flock(2) on the sidecar file "SESSION.lock",
// which holds the holder's pid (for the message). The kernel drops the lock when the holder's
// descriptor closes, including when the process dies by kill -9, so a stale lock file never
// blocks a resume: only a live holder does. The file is left in place (removing it would let
// two processes lock two different inodes of the same name).
#pragma once

#include <string>

namespace accelcal::detail {

class SessionLock {
 public:
  // Takes the lock on `session_path` or throws accelcal::Error
  // "session PATH is open in another accelcal (pid N)".
  explicit SessionLock(const std::string& session_path);
  ~SessionLock();  // releases it
  SessionLock(const SessionLock&) = delete;
  SessionLock& operator=(const SessionLock&) = delete;

 private:
  int fd_ = -1;  // owned; closing it releases the lock
};

}  // namespace accelcal::detail
