#include "accelcal/session/detail/session_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal::detail {
namespace {

std::string ReadHolderPid(const std::string& pid_path) {
  char buffer[32] = {};
  const int fd = open(pid_path.c_str(), O_RDONLY | O_CLOEXEC);
  const ssize_t n = fd < 0 ? -1 : pread(fd, buffer, sizeof(buffer) - 1, 0);
  if (fd >= 0) close(fd);
  std::string pid = n > 0 ? std::string(buffer, static_cast<size_t>(n)) : "";
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid.empty() ? "unknown" : pid;
}

void WritePid(const std::string& pid_path) {
  const std::string pid = std::to_string(getpid()) + "\n";
  // Best effort: the pid only makes the message clearer; the lock itself is the flock.
  const int fd = open(pid_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return;
  if (write(fd, pid.data(), pid.size()) < 0) {
    // nothing to do: the message will say "pid unknown"
  }
  close(fd);
}

}  // namespace

SessionLock::SessionLock(const std::string& session_path) {
  // The lock is on the session file itself (its inode), so a second writer reaching the same
  // file through a symlink or a hard link finds it held. flock(2) locks are independent of the
  // POSIX record locks SQLite takes on the same file (Linux), and this descriptor is closed
  // only after the database (session_store.h), so SQLite's locks are never dropped by it.
  // Opening for writing also refuses a read-only session here, at the start, not at the first
  // capture's commit.
  fd_ = open(session_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    const int err = errno;
    if (err == EACCES || err == EROFS || err == EPERM)
      throw Error(fmt::format("session {} cannot be written ({}): give a session you may write, or "
                              "read this one with `accelcal report`", session_path, std::strerror(err)));
    throw Error(fmt::format("session {}: cannot open it: {}", session_path, std::strerror(err)));
  }
  // SQLite writes its -wal and -journal files beside the session: the folder must be writable.
  const std::string folder = std::filesystem::absolute(session_path).parent_path().string();
  if (access(folder.c_str(), W_OK) != 0) {
    const int err = errno;
    close(fd_);
    fd_ = -1;
    throw Error(fmt::format("session {} cannot be written: its folder {} is not writable ({})", session_path,
                            folder, std::strerror(err)));
  }
  // The holder's pid, for the message only, beside the file's one true name.
  std::error_code ignored;
  const std::filesystem::path real = std::filesystem::weakly_canonical(session_path, ignored);
  pid_path_ = (real.empty() ? std::filesystem::path(session_path) : real).string() + ".lock";
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK)
      throw Error(fmt::format("session {} is open in another accelcal (pid {})", session_path,
                              ReadHolderPid(pid_path_)));
    throw Error(fmt::format("session {}: cannot lock it: {}", session_path, std::strerror(err)));
  }
  WritePid(pid_path_);
}

SessionLock::~SessionLock() {
  if (fd_ >= 0) close(fd_);
}

}  // namespace accelcal::detail
