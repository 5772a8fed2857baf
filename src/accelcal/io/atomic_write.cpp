#include "accelcal/io/atomic_write.h"

#include <cerrno>
#include <cstring>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/io/detail/file_syscalls.h"

namespace accelcal {

namespace {

using detail::CurrentFileSyscalls;

[[noreturn]] void ThrowCannotWrite(const std::string& path, int err) {
  throw Error(fmt::format("cannot write '{}': {}", path, std::strerror(err)));
}

// Closes `fd` keeping the errno of the failure that came before.
void CloseAfterFailure(int fd) {
  const int err = errno;
  CurrentFileSyscalls().close(fd);
  errno = err;
}

// Writes all of `bytes` to `fd`; false with errno set on a failure (a full disk: ENOSPC).
bool WriteAllTo(int fd, std::string_view bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = CurrentFileSyscalls().write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = ENOSPC;
      return false;
    }
    done += static_cast<size_t>(n);
  }
  return true;
}

// The folder that holds `path`, whose entry the rename changes.
std::string FolderOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// The rename into `folder` made durable: the folder's fsync (a rename is a change of the folder,
// which the file's own fsync does not cover). A file system that cannot sync a folder (EINVAL)
// has nothing to make durable; a folder one may write in but not read (mode -wx: EACCES) cannot
// be opened to sync, and the file in it is written as before. False with errno set.
bool SyncFolder(const std::string& folder) {
  const detail::FileSyscalls& sys = CurrentFileSyscalls();
  const int fd = sys.open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC, 0);
  if (fd < 0) return errno == EACCES;
  if (sys.fsync(fd) != 0 && errno != EINVAL) {
    CloseAfterFailure(fd);
    return false;
  }
  return sys.close(fd) == 0;
}

// The end of a write into `tmp` (open as `fd`, closed here whatever happens): its bytes to the
// disk (fsync: a power cut after the rename must not find the new name on an empty or half
// file), the rename over `path`, and the rename to the disk. False with errno set.
bool SyncAndRename(int fd, const std::string& tmp, const std::string& path) {
  const detail::FileSyscalls& sys = CurrentFileSyscalls();
  if (sys.fsync(fd) != 0) {
    CloseAfterFailure(fd);
    return false;
  }
  if (sys.close(fd) != 0) return false;  // a full disk may show only here
  if (sys.rename(tmp.c_str(), path.c_str()) != 0) return false;
  return SyncFolder(FolderOf(path));
}

// Removes `tmp` after a failure, keeping its errno: nothing half written is left behind.
void RemoveAfterFailure(const std::string& tmp) {
  const int err = errno;
  CurrentFileSyscalls().unlink(tmp.c_str());
  errno = err;
}

// A device or a pipe (/dev/stdout, <(...) >, /dev/full) is written in place: renaming a file over
// it would replace the device node, and it has nothing to sync.
bool IsWrittenInPlace(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode);
}

}  // namespace

void WriteFileAtomically(const std::string& path, std::string_view bytes) {
  const detail::FileSyscalls& sys = CurrentFileSyscalls();
  if (IsWrittenInPlace(path)) {
    const int fd = sys.open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) ThrowCannotWrite(path, errno);
    if (!WriteAllTo(fd, bytes)) {
      CloseAfterFailure(fd);
      ThrowCannotWrite(path, errno);
    }
    if (sys.close(fd) != 0) ThrowCannotWrite(path, errno);
    return;
  }
  const std::string tmp = path + ".tmp";
  const int fd = sys.open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  bool ok = fd >= 0;
  if (ok && !WriteAllTo(fd, bytes)) {
    CloseAfterFailure(fd);
    ok = false;
  } else if (ok) {
    ok = SyncAndRename(fd, tmp, path);
  }
  if (!ok) {
    RemoveAfterFailure(tmp);
    ThrowCannotWrite(path, errno);
  }
}

AtomicFileWriter::AtomicFileWriter(std::string path) : path_(std::move(path)) {
  const bool in_place = IsWrittenInPlace(path_);
  if (!in_place) tmp_ = path_ + ".tmp";
  fd_ = in_place ? CurrentFileSyscalls().open(path_.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC, 0644)
                 : CurrentFileSyscalls().open(tmp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) Fail(errno);
}

AtomicFileWriter::~AtomicFileWriter() {
  if (fd_ < 0) return;
  CurrentFileSyscalls().close(fd_);
  if (!tmp_.empty()) CurrentFileSyscalls().unlink(tmp_.c_str());
}

void AtomicFileWriter::Write(std::string_view bytes) {
  if (!WriteAllTo(fd_, bytes)) Fail(errno);
}

void AtomicFileWriter::Commit() {
  const int fd = fd_;
  fd_ = -1;
  const bool ok = tmp_.empty() ? CurrentFileSyscalls().close(fd) == 0 : SyncAndRename(fd, tmp_, path_);
  if (!ok) {
    if (!tmp_.empty()) RemoveAfterFailure(tmp_);
    Fail(errno);
  }
}

void AtomicFileWriter::Fail(int err) { ThrowCannotWrite(path_, err); }

}  // namespace accelcal
