// The atomic write (io/atomic_write.h): what survives a killed writer (the file as it was, or
// the new one whole), and what survives a power cut, seen through the calls it makes (the
// file's fsync before the rename, the folder's after it), recorded by a table of system calls
// that passes each one on to the real one (io/detail/file_syscalls.h).
#include "accelcal/io/atomic_write.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/io/detail/file_syscalls.h"

namespace accelcal {
namespace atomic_write_test {
namespace {

namespace fs = std::filesystem;
using detail::FileSyscalls;
using detail::RealFileSyscalls;
using detail::ScopedFileSyscalls;

// What the calls did, in order: "open PATH", "write PATH", "fsync PATH", "close PATH",
// "rename FROM TO", "unlink PATH" (PATH: what the descriptor was opened on).
std::vector<std::string> calls;
std::map<int, std::string> opened;  // descriptor -> path
int fail_fsync_of_call = -1;        // the n-th fsync (0: the first) fails with EIO

FileSyscalls Recorder() {
  FileSyscalls r;
  r.open = [](const char* path, int flags, mode_t mode) {
    const int fd = RealFileSyscalls().open(path, flags, mode);
    calls.push_back(std::string("open ") + path);
    if (fd >= 0) opened[fd] = path;
    return fd;
  };
  r.write = [](int fd, const void* bytes, size_t size) {
    calls.push_back("write " + opened[fd]);
    return RealFileSyscalls().write(fd, bytes, size);
  };
  r.fsync = [](int fd) {
    calls.push_back("fsync " + opened[fd]);
    if (fail_fsync_of_call-- == 0) {
      errno = EIO;
      return -1;
    }
    return RealFileSyscalls().fsync(fd);
  };
  r.close = [](int fd) {
    calls.push_back("close " + opened[fd]);
    opened.erase(fd);
    return RealFileSyscalls().close(fd);
  };
  r.rename = [](const char* from, const char* to) {
    calls.push_back(std::string("rename ") + from + " " + to);
    return RealFileSyscalls().rename(from, to);
  };
  r.unlink = [](const char* path) {
    calls.push_back(std::string("unlink ") + path);
    return RealFileSyscalls().unlink(path);
  };
  return r;
}

std::string Slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Where `call` is in `calls`; -1 when absent.
int IndexOf(const std::string& call) {
  for (size_t i = 0; i < calls.size(); ++i)
    if (calls[i] == call) return static_cast<int>(i);
  return -1;
}

class AtomicWrite : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("accelcal_atomic_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    path_ = (dir_ / "cal.json").string();
    tmp_ = path_ + ".tmp";
    calls.clear();
    opened.clear();
    fail_fsync_of_call = -1;
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The calls that make the write durable, in the order a power cut needs them.
  void ExpectDurableOrder() {
    const int file_sync = IndexOf("fsync " + tmp_);
    const int rename = IndexOf("rename " + tmp_ + " " + path_);
    const int folder_sync = IndexOf("fsync " + dir_.string());
    ASSERT_GE(file_sync, 0) << "the file was never synced";
    ASSERT_GE(rename, 0) << "never renamed";
    ASSERT_GE(folder_sync, 0) << "the folder was never synced";
    EXPECT_LT(file_sync, IndexOf("close " + tmp_)) << "synced after its close";
    EXPECT_LT(file_sync, rename) << "the new name could point at bytes not yet on the disk";
    EXPECT_GT(folder_sync, rename) << "the rename itself not made durable";
    EXPECT_TRUE(opened.empty()) << "a descriptor left open";
  }

  fs::path dir_;
  std::string path_, tmp_;
};

TEST_F(AtomicWrite, SyncsTheFileBeforeTheRenameAndTheFolderAfter) {
  const FileSyscalls recorder = Recorder();
  ScopedFileSyscalls scoped(recorder);
  WriteFileAtomically(path_, "{\"a\": 1}\n");
  ExpectDurableOrder();
  EXPECT_EQ(Slurp(path_), "{\"a\": 1}\n");
  EXPECT_FALSE(fs::exists(tmp_));
}

TEST_F(AtomicWrite, WriterInPiecesSyncsTheSameWay) {
  const FileSyscalls recorder = Recorder();
  ScopedFileSyscalls scoped(recorder);
  {
    AtomicFileWriter writer(path_);
    writer.Write("0.01 1 2 3\n");
    writer.Write("0.02 1 2 3\n");
    EXPECT_EQ(IndexOf("fsync " + tmp_), -1) << "synced before the commit";
    writer.Commit();
  }
  ExpectDurableOrder();
  EXPECT_EQ(Slurp(path_), "0.01 1 2 3\n0.02 1 2 3\n");
}

TEST_F(AtomicWrite, BareFileNameSyncsTheCurrentFolder) {
  const fs::path cwd = fs::current_path();
  fs::current_path(dir_);
  const FileSyscalls recorder = Recorder();
  {
    ScopedFileSyscalls scoped(recorder);
    WriteFileAtomically("bare.txt", "x\n");
  }
  fs::current_path(cwd);
  EXPECT_GT(IndexOf("fsync ."), IndexOf("rename bare.txt.tmp bare.txt"));
  EXPECT_EQ(Slurp((dir_ / "bare.txt").string()), "x\n");
}

// A disk that fails the sync (EIO): the write is refused in the usual words, the old file is as
// it was and no PATH.tmp is left.
TEST_F(AtomicWrite, FailedSyncKeepsTheOldFile) {
  WriteFileAtomically(path_, "old\n");
  const FileSyscalls recorder = Recorder();
  ScopedFileSyscalls scoped(recorder);
  fail_fsync_of_call = 0;
  try {
    WriteFileAtomically(path_, "new\n");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write '" + path_ + "': Input/output error");
  }
  EXPECT_EQ(IndexOf("rename " + tmp_ + " " + path_), -1) << "renamed unsynced bytes into place";
  EXPECT_EQ(Slurp(path_), "old\n");
  EXPECT_FALSE(fs::exists(tmp_));
  EXPECT_TRUE(opened.empty());

  calls.clear();
  fail_fsync_of_call = 0;
  try {
    AtomicFileWriter writer(path_);
    writer.Write("new\n");
    writer.Commit();
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write '" + path_ + "': Input/output error");
  }
  EXPECT_EQ(Slurp(path_), "old\n");
  EXPECT_FALSE(fs::exists(tmp_));
}

// The folder's sync failing: the file is in place but its rename may not survive a power cut,
// which the writer must hear of.
TEST_F(AtomicWrite, FailedFolderSyncIsAnError) {
  const FileSyscalls recorder = Recorder();
  ScopedFileSyscalls scoped(recorder);
  fail_fsync_of_call = 1;  // the file's passes, the folder's fails
  EXPECT_THROW(WriteFileAtomically(path_, "new\n"), Error);
  EXPECT_GT(IndexOf("fsync " + dir_.string()), IndexOf("rename " + tmp_ + " " + path_));
  EXPECT_TRUE(opened.empty());
}

// A device is written in place: no rename, nothing to sync (/dev/null refuses fsync).
TEST_F(AtomicWrite, DeviceIsWrittenInPlace) {
  const FileSyscalls recorder = Recorder();
  ScopedFileSyscalls scoped(recorder);
  WriteFileAtomically("/dev/null", "x\n");
  AtomicFileWriter writer("/dev/null");
  writer.Write("y\n");
  writer.Commit();
  for (const std::string& c : calls) {
    EXPECT_EQ(c.rfind("rename", 0), std::string::npos) << c;
    EXPECT_EQ(c.rfind("fsync", 0), std::string::npos) << c;
  }
}

// A writer killed (SIGKILL) while it rewrites the file again and again, each version 512 KiB of
// one repeated line: the file is always one whole version, never a mix or a cut, and never
// older than the last version the writer said was written.
TEST_F(AtomicWrite, KilledWriterLeavesOneWholeVersion) {
  constexpr int kLines = 512 * 1024 / 8;
  auto version = [](long k) {
    char line[32];
    std::snprintf(line, sizeof line, "%07ld\n", k % 10000000);  // 8 bytes: k >= 0
    std::string text;
    text.reserve(kLines * 8);
    for (int i = 0; i < kLines; ++i) text.append(line, 8);
    return text;
  };
  WriteFileAtomically(path_, version(0));
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    for (long k = 1;; ++k) {
      WriteFileAtomically(path_, version(k));
      const std::string said = std::to_string(k) + "\n";
      if (write(fds[1], said.data(), said.size()) < 0) _exit(1);
    }
  }
  close(fds[1]);
  std::string said;
  char buffer[64];
  while (said.find('\n') == std::string::npos) {
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    if (n <= 0) break;
    said.append(buffer, static_cast<size_t>(n));
  }
  usleep(20000);
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;) said.append(buffer, static_cast<size_t>(n));
  close(fds[0]);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the writer was not killed";

  long last_said = 0;
  std::istringstream lines(said);
  for (std::string line; std::getline(lines, line);) last_said = std::stol(line);
  ASSERT_GE(last_said, 1) << "the writer never finished a version";
  const std::string text = Slurp(path_);
  ASSERT_EQ(text.size(), static_cast<size_t>(kLines) * 8) << "a cut version";
  const long k = std::stol(text.substr(0, 7));
  EXPECT_TRUE(text == version(k)) << "a mix of versions";
  EXPECT_GE(k, last_said) << "older than a version the writer had written";
  // The next write goes through (over whatever PATH.tmp the killed writer left).
  WriteFileAtomically(path_, "after\n");
  EXPECT_EQ(Slurp(path_), "after\n");
  EXPECT_FALSE(fs::exists(tmp_));
}

}  // namespace
}  // namespace atomic_write_test
}  // namespace accelcal
