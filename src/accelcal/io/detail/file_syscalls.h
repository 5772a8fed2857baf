// The system calls behind an atomic write (atomic_write.h), in one table a test can replace: the
// order of the calls (the file's fsync before the rename, the folder's after it) is what makes a
// written file survive a power cut, and nothing else a test can observe shows it.
#pragma once

#include <sys/types.h>

#include <cstddef>

namespace accelcal::detail {

struct FileSyscalls {
  int (*open)(const char* path, int flags, mode_t mode);
  ssize_t (*write)(int fd, const void* bytes, size_t size);
  int (*fsync)(int fd);
  int (*close)(int fd);
  int (*rename)(const char* from, const char* to);
  int (*unlink)(const char* path);
};

// The operating system's calls.
const FileSyscalls& RealFileSyscalls();

// The table atomic writes use: the real one unless a ScopedFileSyscalls is alive.
const FileSyscalls& CurrentFileSyscalls();

// Makes `calls` the current table for its lifetime (tests: one at a time, on one thread). The
// table is borrowed: it must outlive this object.
class ScopedFileSyscalls {
 public:
  explicit ScopedFileSyscalls(const FileSyscalls& calls);
  ~ScopedFileSyscalls();
  ScopedFileSyscalls(const ScopedFileSyscalls&) = delete;
  ScopedFileSyscalls& operator=(const ScopedFileSyscalls&) = delete;

 private:
  const FileSyscalls* previous_;
};

}  // namespace accelcal::detail
