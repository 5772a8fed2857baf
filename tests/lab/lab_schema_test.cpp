// The lab store's schema: created and migrated by accelcal, from an empty database and from each
// earlier version with data in it; what a bench does with a store older or newer than it knows.
#include <algorithm>
#include <thread>

#include "lab_test_support.h"

namespace accelcal {
namespace {

using testing::kAdmin;
using testing::kManager;
using testing::kOutsider;
using testing::MakePublication;
using testing::NumberedRenderer;

class LabSchema : public testing::LabDatabaseTest {};

std::vector<int> AppliedVersions(detail::PgConnection& db) {
  const detail::PgResult r = db.Exec("SELECT version FROM accelcal.schema_migrations ORDER BY version");
  std::vector<int> versions;
  for (int i = 0; i < r.rows(); ++i) versions.push_back(static_cast<int>(r.Int(i, 0)));
  return versions;
}

std::vector<int> AllVersions() {
  std::vector<int> all;
  for (const LabMigration& m : LabMigrations()) all.push_back(m.version);
  return all;
}

TEST_F(LabSchema, TheMigrationsAreNumberedOneByOne) {
  ASSERT_EQ(static_cast<int>(LabMigrations().size()), kLabSchemaVersion);
  for (size_t i = 0; i < LabMigrations().size(); ++i)
    EXPECT_EQ(LabMigrations()[i].version, static_cast<int>(i) + 1);
}

TEST_F(LabSchema, AnEmptyDatabaseIsMigratedToTheLatestVersionOnce) {
  {
    const auto admin = As(kAdmin, true);
    EXPECT_EQ(admin->SchemaState().version, 0);
    EXPECT_FALSE(admin->SchemaState().usable);
    EXPECT_NE(admin->SchemaState().problem.find("accelcal lab migrate"), std::string::npos);
    EXPECT_EQ(admin->Migrate(), AllVersions());
    EXPECT_TRUE(admin->Migrate().empty());  // nothing to do the second time
    EXPECT_TRUE(admin->SchemaState().usable);
  }
  auto raw = RawAs(kAdmin);
  EXPECT_EQ(AppliedVersions(*raw), AllVersions());
}

// Each earlier version, with what a lab would have put in it by then (published sessions, a
// certificate approved, one withdrawn, a device type from version 2 on), reaches the latest:
// the data is kept and the later versions' features work on it.
TEST_F(LabSchema, EachEarlierVersionWithDataIsMigratedToTheLatest) {
  for (int from = 1; from < kLabSchemaVersion; ++from) {
    SCOPED_TRACE(fmt::format("from version {}", from));
    TearDown();
    SetUp();
    Migrate(from);
    std::vector<std::string> numbers;
    {
      const auto bench = As("bench_1", true);  // (a bench of that time: no check of the version)
      for (int i = 0; i < 3; ++i) {
        const std::string date = fmt::format("2025-0{}-10T09:00:00.000Z", i + 1);
        const LabPublishResult r =
            bench->Publish(MakePublication(NewRandomUuid(), "OLD-7", date), NumberedRenderer());
        numbers.push_back(r.certificates.at(0).certificate_number);
      }
    }
    {
      const auto manager = As(kManager, true);
      manager->SetCertificateStatus(numbers[0], LabCertificateStatus::kApproved);
      manager->SetCertificateStatus(numbers[2], LabCertificateStatus::kWithdrawn, "wrong gravity");
      if (from >= 2) {
        manager->SetDeviceTypeInterval("MMA7260Q", 180);
        manager->SetDeviceType("OLD-7", "MMA7260Q");
      }
    }
    ASSERT_THROW(As("bench_1"), LabError);  // an older register: the bench is told to migrate
    {
      const auto admin = As(kAdmin, true);
      std::vector<int> expected;
      for (int v = from + 1; v <= kLabSchemaVersion; ++v) expected.push_back(v);
      EXPECT_EQ(admin->Migrate(), expected);
    }
    const auto bench = As("bench_2");
    const LabHistory h = bench->History("OLD-7");
    ASSERT_EQ(h.entries.size(), 3u);
    EXPECT_EQ(h.entries[0].certificate_number, numbers[0]);
    EXPECT_EQ(h.entries[0].status, "approved");
    EXPECT_EQ(h.entries[0].approved_by, kManager);
    EXPECT_EQ(h.entries[1].status, "issued");
    EXPECT_EQ(h.entries[2].status, "withdrawn");
    EXPECT_EQ(h.entries[2].withdrawn_reason, "wrong gravity");
    EXPECT_EQ(h.entries[2].bench, "bench_1");
    // Due: the last valid calibration is the second (the third is withdrawn), 2025-02-10, plus
    // the type's 180 days (version 2 on) or the lab's default 365 (set by version 2's migration).
    const LabDueList due = bench->Due(100000);
    ASSERT_EQ(due.items.size(), 1u);
    EXPECT_EQ(due.items[0].id, "OLD-7");
    EXPECT_EQ(due.items[0].last, numbers[1]);
    EXPECT_EQ(due.items[0].due_date, from >= 2 ? "2025-08-09" : "2026-02-10");
    EXPECT_EQ(h.device_type, from >= 2 ? "MMA7260Q" : "");
    // The documents as stored, untouched.
    const std::vector<LabDocument> docs = bench->CertificateDocuments(numbers[1]);
    ASSERT_EQ(docs.size(), 2u);
    EXPECT_NE(docs[0].bytes.find(numbers[1]), std::string::npos);
  }
}

TEST_F(LabSchema, TwoAdministratorsMigratingAtOnceApplyEachVersionOnce) {
  std::vector<int> applied[2];
  std::string errors[2];
  {
    testing::ScopedEnv user("PGUSER", kAdmin);
    std::vector<std::thread> threads;
    for (int t = 0; t < 2; ++t)
      threads.emplace_back([&, t] {
        try {
          applied[t] = LabStore::Connect(true)->Migrate();
        } catch (const std::exception& e) {
          errors[t] = e.what();
        }
      });
    for (std::thread& t : threads) t.join();
  }
  EXPECT_EQ(errors[0], "");
  EXPECT_EQ(errors[1], "");
  std::vector<int> both = applied[0];
  both.insert(both.end(), applied[1].begin(), applied[1].end());
  std::sort(both.begin(), both.end());
  EXPECT_EQ(both, AllVersions());
  auto raw = RawAs(kAdmin);
  EXPECT_EQ(AppliedVersions(*raw), AllVersions());
}

TEST_F(LabSchema, ANewerRegisterThatOnlyAddsIsUsedOneThatBreaksIsRefused) {
  Migrate();
  auto admin = RawAs(kAdmin);
  admin->Exec(
      "INSERT INTO accelcal.schema_migrations (version, description, older_clients_ok) "
      "VALUES ($1, 'a later addition', true)",
      {detail::PgInt(kLabSchemaVersion + 1)});
  EXPECT_NO_THROW(As("bench_1")->Due(30));
  admin->Exec(
      "INSERT INTO accelcal.schema_migrations (version, description, older_clients_ok) "
      "VALUES ($1, 'a later change', false)",
      {detail::PgInt(kLabSchemaVersion + 2)});
  try {
    As("bench_1");
    FAIL() << "a register this accelcal cannot work with was used";
  } catch (const LabError& e) {
    EXPECT_NE(std::string(e.what()).find("update accelcal on this bench"), std::string::npos) << e.what();
  }
}

TEST_F(LabSchema, ARoleOutsideTheLabIsToldWhatItLacks) {
  Migrate();
  try {
    As(kOutsider);
    FAIL() << "a role of neither group was let in";
  } catch (const LabError& e) {
    EXPECT_NE(std::string(e.what()).find("GRANT accelcal_bench TO visitor_1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace accelcal
