// Schema version 6 of the session store: a session's identity (a UUID, what a lab's store keys
// it by) and the lab certificate numbers written back into it after publishing (docs/lab.md).
#include <filesystem>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/base/uuid.h"
#include "accelcal/session/session_store.h"
#include "session_test_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

namespace fs = std::filesystem;
using testing::Contains;

using SessionLabIdentity = testing::SessionDirTest;

TEST_F(SessionLabIdentity, ASessionHasOneIdentityThatACopyKeeps) {
  std::string uuid;
  {
    auto store = SessionStore::Open(path_, Writer());
    uuid = store->Info().uuid;
    EXPECT_TRUE(IsUuidText(uuid)) << uuid;
  }
  EXPECT_EQ(SessionStore::Open(path_, Reader())->Info().uuid, uuid);
  EXPECT_EQ(SessionStore::Open(path_, Writer())->Info().uuid, uuid);  // a writer's reopen keeps it
  fs::copy_file(path_, (dir_ / "copy.db").string());
  EXPECT_EQ(SessionStore::Open((dir_ / "copy.db").string(), Reader())->Info().uuid, uuid);
  const std::string other = (dir_ / "other.db").string();
  EXPECT_NE(SessionStore::Open(other, Writer())->Info().uuid, uuid);
}

// A version-4 session (tests/data/session/) read as it is has no identity and no lab numbers; the
// first writer gives it one, once.
TEST_F(SessionLabIdentity, AnOlderSessionGetsItsIdentityWhenMigrated) {
  fs::copy_file(std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/session/v4_two_poses.db", path_);
  {
    auto reader = SessionStore::Open(path_, Reader());
    EXPECT_EQ(reader->Info().uuid, "");
    EXPECT_TRUE(reader->LabCertificates().empty());
    EXPECT_EQ(reader->Info().num_lab_certificates, 0);
  }
  std::string uuid = SessionStore::Open(path_, Writer())->Info().uuid;
  EXPECT_TRUE(IsUuidText(uuid)) << uuid;
  EXPECT_EQ(SessionStore::Open(path_, Writer())->Info().uuid, uuid);
  EXPECT_EQ(SessionStore::Open(path_, Reader())->Captures().size(), 2u);
}

TEST_F(SessionLabIdentity, ALabNumberIsWrittenBackOnceAndNeverReplaced) {
  std::string updated;
  {
    auto store = SessionStore::Open(path_, Writer());
    store->RecordInput("welcome", "device", "SIM-0001");
    updated = store->Info().updated_utc;
    store->RecordLabCertificate({0, "LAB-000042", "lab 1234 (database lab)", "2026-11-27T08:00:00.000Z"});
    store->RecordLabCertificate(
        {0, "LAB-000042", "lab 1234 (database lab)", "2026-11-27T08:00:00.000Z"});  // again: nothing
    try {
      store->RecordLabCertificate({0, "LAB-000043", "lab 1234 (database lab)", "2026-11-27T08:01:00.000Z"});
      FAIL() << "a second number replaced the first";
    } catch (const Error& e) {
      EXPECT_TRUE(Contains(e.what(), "already holds certificate LAB-000042")) << e.what();
    }
  }
  auto reader = SessionStore::Open(path_, Reader());
  const std::vector<LabCertificateMark> marks = reader->LabCertificates();
  ASSERT_EQ(marks.size(), 1u);
  EXPECT_EQ(marks[0].sensor_index, 0);
  EXPECT_EQ(marks[0].certificate_number, "LAB-000042");
  EXPECT_EQ(marks[0].lab, "lab 1234 (database lab)");
  EXPECT_EQ(marks[0].published_utc, "2026-11-27T08:00:00.000Z");
  EXPECT_EQ(reader->Info().num_lab_certificates, 1);
  // Publishing changes nothing the session recorded: its date stays the calibration's.
  EXPECT_EQ(reader->Info().updated_utc, updated);
  EXPECT_THROW(reader->RecordLabCertificate({1, "LAB-000044", "lab", "now"}), Error);
}

TEST(Uuid, NewOnesAreVersionFourAndDistinct) {
  const std::string a = NewRandomUuid(), b = NewRandomUuid();
  EXPECT_TRUE(IsUuidText(a)) << a;
  EXPECT_NE(a, b);
  EXPECT_EQ(a[14], '4');
  EXPECT_NE(std::string("89ab").find(a[19]), std::string::npos) << a;
  EXPECT_FALSE(IsUuidText("3F2B8C1E-9D4A-4E6B-8F0C-2A5D7E9B1C34"));  // upper case: not our form
  EXPECT_FALSE(IsUuidText("3f2b8c1e9d4a-4e6b-8f0c-2a5d7e9b1c34-"));
  EXPECT_FALSE(IsUuidText(""));
}

}  // namespace
}  // namespace accelcal
