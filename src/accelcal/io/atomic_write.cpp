#include "accelcal/io/atomic_write.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal {

namespace {

// Writes all of `bytes` to `path` (created or truncated) and closes it; false with errno set on
// any failure (a full disk shows at the write or at the close).
bool WriteAll(const std::string& path, std::string_view bytes, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC, 0644);
  if (fd < 0) return false;
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : ENOSPC;
      ::close(fd);
      errno = err;
      return false;
    }
    done += static_cast<size_t>(n);
  }
  return ::close(fd) == 0;
}

}  // namespace

void WriteFileAtomically(const std::string& path, std::string_view bytes) {
  // A device or a pipe (/dev/stdout, <(...) >, /dev/full) is written in place: renaming a file
  // over it would replace the device node.
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) {
    if (!WriteAll(path, bytes, O_WRONLY | O_TRUNC))
      throw Error(fmt::format("cannot write '{}': {}", path, std::strerror(errno)));
    return;
  }
  const std::string tmp = path + ".tmp";
  if (!WriteAll(tmp, bytes, O_WRONLY | O_CREAT | O_TRUNC)) {
    const int err = errno;
    std::remove(tmp.c_str());  // nothing half written is left behind
    throw Error(fmt::format("cannot write '{}': {}", path, std::strerror(err)));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    std::remove(tmp.c_str());
    throw Error(fmt::format("cannot write '{}': {}", path, std::strerror(err)));
  }
}

AtomicFileWriter::AtomicFileWriter(std::string path) : path_(std::move(path)) {
  struct stat info {};
  const bool in_place = ::stat(path_.c_str(), &info) == 0 && !S_ISREG(info.st_mode);
  if (!in_place) tmp_ = path_ + ".tmp";
  fd_ = in_place ? ::open(path_.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC)
                 : ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) Fail(errno);
}

AtomicFileWriter::~AtomicFileWriter() {
  if (fd_ >= 0) ::close(fd_);
  if (fd_ >= 0 && !tmp_.empty()) std::remove(tmp_.c_str());
}

void AtomicFileWriter::Write(std::string_view bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) Fail(n < 0 ? errno : ENOSPC);
    done += static_cast<size_t>(n);
  }
}

void AtomicFileWriter::Commit() {
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0 || (!tmp_.empty() && std::rename(tmp_.c_str(), path_.c_str()) != 0)) {
    const int err = errno;
    if (!tmp_.empty()) std::remove(tmp_.c_str());
    throw Error(fmt::format("cannot write '{}': {}", path_, std::strerror(err)));
  }
}

void AtomicFileWriter::Fail(int err) {
  throw Error(fmt::format("cannot write '{}': {}", path_, std::strerror(err)));
}

}  // namespace accelcal
