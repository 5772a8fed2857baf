// Issue 17, item 10: the one-writer lock holds the session file itself, whatever name reaches
// it (a symlink, a hard link), and a session that cannot be written is refused when opened, not
// at the first capture's commit.
#include <sys/mount.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/session/session_store.h"
#include "session_test_support.h"

namespace accelcal {
namespace {

namespace fs = std::filesystem;

class SessionLockTest : public testing::SessionDirTest {
 protected:
  std::string SecondWriterRefusal(const std::string& other_name) {
    try {
      SessionStore::Open(other_name, Writer());
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(SessionLockTest, ASymlinkReachesTheSameLock) {
  auto store = SessionStore::Open(path_, Writer());
  const std::string link = (dir_ / "link.db").string();
  fs::create_symlink(path_, link);
  const std::string why = SecondWriterRefusal(link);
  EXPECT_NE(why.find("is open in another accelcal (pid " + std::to_string(getpid()) + ")"), std::string::npos)
      << why;
}

TEST_F(SessionLockTest, AHardLinkReachesTheSameLock) {
  auto store = SessionStore::Open(path_, Writer());
  const std::string link = (dir_ / "hard.db").string();
  fs::create_hard_link(path_, link);
  EXPECT_NE(SecondWriterRefusal(link).find("is open in another accelcal"), std::string::npos);
}

TEST_F(SessionLockTest, TheLockIsFreeAgainAfterClose) {
  SessionStore::Open(path_, Writer()).reset();
  fs::create_symlink(path_, dir_ / "link.db");
  EXPECT_NO_THROW(SessionStore::Open((dir_ / "link.db").string(), Writer()));
}

// A read-only file system (a tmpfs remounted read-only) refuses even root. Skipped where this
// process may not mount (an unprivileged CI runner): the read-only file mode covers it there.
TEST_F(SessionLockTest, AReadOnlySessionIsRefusedAtOpen) {
  SessionStore::Open(path_, Writer()).reset();
  if (geteuid() != 0) {
    fs::permissions(path_, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  } else {
    const fs::path mount_dir = dir_ / "ro";
    fs::create_directories(mount_dir);
    if (::mount("tmpfs", mount_dir.c_str(), "tmpfs", 0, "size=1m") != 0) GTEST_SKIP() << "cannot mount a tmpfs";
    fs::copy_file(path_, mount_dir / "s.db");
    const bool remounted = ::mount("tmpfs", mount_dir.c_str(), "tmpfs", MS_REMOUNT | MS_RDONLY, "size=1m") == 0;
    std::string why;
    try {
      SessionStore::Open((mount_dir / "s.db").string(), Writer());
    } catch (const Error& e) {
      why = e.what();
    }
    ::umount(mount_dir.c_str());
    if (!remounted) GTEST_SKIP() << "cannot remount read-only";
    EXPECT_NE(why.find("cannot be written"), std::string::npos) << why;
    return;
  }
  std::string why;
  try {
    SessionStore::Open(path_, Writer());
  } catch (const Error& e) {
    why = e.what();
  }
  EXPECT_NE(why.find("cannot be written"), std::string::npos) << why;
}

}  // namespace
}  // namespace accelcal
