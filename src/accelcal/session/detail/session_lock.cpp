#include "accelcal/session/detail/session_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal::detail {
namespace {

std::string ReadHolderPid(int fd) {
  char buffer[32] = {};
  const ssize_t n = pread(fd, buffer, sizeof(buffer) - 1, 0);
  std::string pid = n > 0 ? std::string(buffer, static_cast<size_t>(n)) : "";
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid.empty() ? "unknown" : pid;
}

void WritePid(int fd) {
  const std::string pid = std::to_string(getpid()) + "\n";
  // Best effort: the pid only makes the message clearer; the lock itself is the flock.
  if (ftruncate(fd, 0) == 0 && pwrite(fd, pid.data(), pid.size(), 0) < 0) return;
}

}  // namespace

SessionLock::SessionLock(const std::string& session_path) {
  const std::string lock_path = session_path + ".lock";
  fd_ = open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw Error(fmt::format("session {}: cannot open the lock file {}: {}", session_path,
                            lock_path, std::strerror(errno)));
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    const std::string pid = ReadHolderPid(fd_);
    close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK)
      throw Error(fmt::format("session {} is open in another accelcal (pid {})", session_path, pid));
    throw Error(fmt::format("session {}: cannot lock {}: {}", session_path, lock_path,
                            std::strerror(err)));
  }
  WritePid(fd_);
}

SessionLock::~SessionLock() {
  if (fd_ >= 0) close(fd_);
}

}  // namespace accelcal::detail
