#include "accelcal/acquire/source/file_link.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

// An already-open descriptor, owned (a file) or borrowed (standard input).
class FdLink final : public ByteLink {
 public:
  FdLink(std::string spec, int fd, bool owned) : spec_(std::move(spec)), fd_(fd), owned_(owned) {}
  ~FdLink() override { Close(); }

  std::string Describe() const override { return spec_; }
  OpenStep Open(double /*timeout_s*/, std::string* error) override {
    if (fd_ >= 0) return OpenStep::kOpen;
    *error = "closed";
    return OpenStep::kFailed;
  }
  int fd() const override { return fd_; }
  void Close() override {
    if (owned_ && fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  bool reopens() const override { return false; }

 private:
  std::string spec_;
  int fd_;
  bool owned_;
};

}  // namespace

std::unique_ptr<ByteLink> OpenFileLink(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error("cannot open '" + path + "': " + std::strerror(errno));
  // A folder opens for reading but every read fails (EISDIR), which a stream takes for its
  // end: "ended, 0 samples". Refuse it here, with the reason.
  struct stat info {};
  if (::fstat(fd, &info) == 0 && S_ISDIR(info.st_mode)) {
    ::close(fd);
    throw Error("cannot read '" + path + "': it is a folder, not a file of samples");
  }
  return std::make_unique<FdLink>("file:" + path, fd, true);
}

std::unique_ptr<ByteLink> MakeStdinLink(int fd) {
  return std::make_unique<FdLink>("-", fd, false);
}

}  // namespace accelcal
