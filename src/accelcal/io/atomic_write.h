// Writing a whole file so that a crash never leaves it half written, and a power cut neither:
// the bytes go to PATH.tmp, which is synced to the disk (fsync) and then renamed over PATH
// (atomic on POSIX file systems), and the rename is synced too (fsync of PATH's folder). Until
// the rename PATH is as it was; after a power cut it is the old file or the new one, whole. The
// calls are detail/file_syscalls.h's, which a test can watch.
#pragma once

#include <string>
#include <string_view>

namespace accelcal {

// Throws accelcal::Error "cannot write 'PATH': <reason>" (a full disk: "No space left on
// device"; a failed sync: "Input/output error"), leaving PATH as it was and no PATH.tmp behind;
// a failed sync of the folder, after the rename, is the same error (PATH is the new file, but
// the rename may not survive a power cut). A PATH that is not a regular file (a device such as
// /dev/stdout, a pipe) is written in place, with nothing to sync.
void WriteFileAtomically(const std::string& path, std::string_view bytes);

// The same for a file written piece by piece (a long recording, in bounded memory): the pieces
// go to PATH.tmp, renamed over PATH by Commit(). Destroyed without Commit() (an error on the
// way), PATH.tmp is removed and PATH is as it was. Errors as WriteFileAtomically's.
class AtomicFileWriter {
 public:
  explicit AtomicFileWriter(std::string path);
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  void Write(std::string_view bytes);
  void Commit();

 private:
  [[noreturn]] void Fail(int err);

  std::string path_;
  std::string tmp_;  // empty: written in place (not a regular file)
  int fd_ = -1;
};

}  // namespace accelcal
