#include "accelcal/io/text_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>

#include "accelcal/io/detail/read_file.h"

namespace accelcal {

std::string ReadTextFile(const std::string& path) { return detail::ReadWholeFile(path); }

bool IsReadOnceInput(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return false;
  return S_ISFIFO(info.st_mode) || S_ISCHR(info.st_mode) || S_ISSOCK(info.st_mode);
}

void TruncateToLastWholeLine(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  if (fd < 0) return;
  struct stat info {};
  off_t keep = 0;
  if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode)) {
    char block[4096];
    for (off_t end = info.st_size; end > 0 && keep == 0;) {
      const off_t start = std::max<off_t>(0, end - static_cast<off_t>(sizeof block));
      const ssize_t n = ::pread(fd, block, static_cast<size_t>(end - start), start);
      if (n <= 0) break;
      for (ssize_t i = n - 1; i >= 0; --i)
        if (block[i] == '\n') {
          keep = start + i + 1;
          break;
        }
      end = start;
    }
    if (keep < info.st_size && ::ftruncate(fd, keep) != 0) {
      // nothing more to do: the caller already reports the failed write
    }
  }
  ::close(fd);
}

}  // namespace accelcal
