// The one-writer lock of a session: an exclusive flock(2) on the session file itself (its
// inode: a symlink or a hard link to it reaches the same lock), with the holder's pid written
// to the sidecar "SESSION.lock" beside the file's canonical name (for the message only). The kernel drops the lock when the holder's
// descriptor closes, including when the process dies by kill -9, so a stale lock file never
// blocks a resume: only a live holder does. The file is left in place (removing it would let
// two processes lock two different inodes of the same name).
#pragma once

#include <string>

namespace accelcal::detail {

class SessionLock {
 public:
  // Takes the lock on `session_path` or throws accelcal::Error
  // "session PATH is open in another accelcal (pid N)", or "session PATH cannot be written"
  // when the file or its folder is read-only. Creates an empty file when none exists (SQLite
  // takes an empty file as an empty database).
  explicit SessionLock(const std::string& session_path);
  ~SessionLock();  // releases it
  SessionLock(const SessionLock&) = delete;
  SessionLock& operator=(const SessionLock&) = delete;

 private:
  int fd_ = -1;  // owned; closing it releases the lock
  std::string pid_path_;
};

}  // namespace accelcal::detail
