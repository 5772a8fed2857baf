// Issue 17, item 5: a session copied while its writer runs (or after a kill -9) without its
// -wal file: every accepted capture is in the file itself (checkpointed at each capture), and a
// copy that holds nothing yet says that its -wal is missing, not "a file of another program".
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/session/session_store.h"
#include "session_test_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

namespace fs = std::filesystem;

Capture SmallCapture(int id) {
  Capture c;
  c.id = id;
  c.kind = CaptureKind::kStatic;
  c.label = "pose " + std::to_string(id);
  for (int k = 0; k < 20; ++k) {
    Sample s;
    s.t_s = 10.0 * id + k / 100.0;
    s.raw_counts = Eigen::Vector3d(2048 + k % 3, 2047.5, 2400 - k % 2);
    c.samples.push_back(s);
  }
  return c;
}

class SessionCopyTest : public testing::SessionDirTest {
 protected:
  // The session file alone, copied while the writer still has it open.
  std::string CopyWithoutWal() {
    const std::string copy = (dir_ / "copy.db").string();
    fs::copy_file(path_, copy);
    EXPECT_FALSE(fs::exists(copy + "-wal"));
    return copy;
  }
};

TEST_F(SessionCopyTest, ACopyWithoutWalHoldsEveryAcceptedCapture) {
  auto store = SessionStore::Open(path_, Writer());
  store->RecordCapture("face_1", SmallCapture(1));
  store->RecordCapture("face_2", SmallCapture(2));
  const std::string copy = CopyWithoutWal();
  EXPECT_EQ(SessionStore::Open(copy, Reader())->Captures().size(), 2u);
}

TEST_F(SessionCopyTest, ACopyThatHoldsNothingYetNamesTheMissingWal) {
  auto store = SessionStore::Open(path_, Writer());  // the schema is in the -wal only
  const std::string copy = CopyWithoutWal();
  for (bool read_only : {true, false}) {
    std::string why;
    try {
      SessionStore::Open(copy, read_only ? Reader() : Writer());
    } catch (const Error& e) {
      why = e.what();
    }
    EXPECT_NE(why.find("copy.db-wal, which is not beside it"), std::string::npos) << why;
    EXPECT_EQ(why.find("another program"), std::string::npos) << why;
    fs::remove(copy + "-wal");
    fs::remove(copy + "-shm");
  }
}

}  // namespace
}  // namespace accelcal
