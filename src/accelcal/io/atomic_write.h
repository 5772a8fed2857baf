// Writing a whole file so that a crash never leaves it half written: the bytes go to PATH.tmp,
// which is then renamed over PATH (atomic on POSIX file systems).
#pragma once

#include <string>
#include <string_view>

namespace accelcal {

// Throws accelcal::Error "cannot write 'PATH': <reason>" (a full disk: "No space left on
// device"), leaving PATH as it was and no PATH.tmp behind. A PATH that is not a regular file (a
// device such as /dev/stdout, a pipe) is written in place.
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
