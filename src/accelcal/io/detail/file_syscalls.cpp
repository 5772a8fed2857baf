#include "accelcal/io/detail/file_syscalls.h"

#include <cstdio>

#include <fcntl.h>
#include <unistd.h>

namespace accelcal::detail {

namespace {

const FileSyscalls kRealFileSyscalls = {
    [](const char* path, int flags, mode_t mode) { return ::open(path, flags, mode); },
    [](int fd, const void* bytes, size_t size) { return ::write(fd, bytes, size); },
    [](int fd) { return ::fsync(fd); },
    [](int fd) { return ::close(fd); },
    [](const char* from, const char* to) { return std::rename(from, to); },
    [](const char* path) { return ::unlink(path); },
};

const FileSyscalls* current_file_syscalls = &kRealFileSyscalls;

}  // namespace

const FileSyscalls& RealFileSyscalls() { return kRealFileSyscalls; }

const FileSyscalls& CurrentFileSyscalls() { return *current_file_syscalls; }

ScopedFileSyscalls::ScopedFileSyscalls(const FileSyscalls& calls) : previous_(current_file_syscalls) {
  current_file_syscalls = &calls;
}

ScopedFileSyscalls::~ScopedFileSyscalls() { current_file_syscalls = previous_; }

}  // namespace accelcal::detail
