// What each role may do is decided by the database (grants, row-level security, the schema's
// triggers), not by accelcal: each refusal here comes back from PostgreSQL with SQLSTATE 42501
// (insufficient_privilege), tried through accelcal and, for what accelcal never sends, by SQL.
#include "lab_test_support.h"

namespace accelcal {
namespace {

using detail::PgText;
using testing::kAdmin;
using testing::kManager;
using testing::MakePublication;
using testing::NumberedRenderer;

class LabRoles : public testing::LabDatabaseTest {
 protected:
  bool StartMigrated() const override { return true; }
  void SetUp() override {
    LabDatabaseTest::SetUp();
    uuid_ = NewRandomUuid();
    number_ = As("bench_1")
                  ->Publish(MakePublication(uuid_, "DEV-1"), NumberedRenderer())
                  .certificates.at(0)
                  .certificate_number;
  }

  // Runs `fn`, which the database must refuse with `sqlstate`; returns the message.
  template <typename Fn>
  static std::string Refused(Fn&& fn, const std::string& sqlstate = kSqlStateRefused) {
    try {
      fn();
    } catch (const LabError& e) {
      EXPECT_EQ(e.sqlstate(), sqlstate) << e.what();
      return e.what();
    }
    ADD_FAILURE() << "not refused";
    return "";
  }

  static std::string Status(const std::string& number) {
    return RawAs(kAdmin)
        ->Exec("SELECT status FROM accelcal.certificates WHERE certificate_number = $1", {PgText(number)})
        .Text(0, 0);
  }

  std::string uuid_;
  std::string number_;
};

TEST_F(LabRoles, ABenchPublishesAndReadsEveryBenchsWork) {
  As("bench_2")->Publish(MakePublication(NewRandomUuid(), "DEV-1", "2026-02-01T00:00:00.000Z"),
                         NumberedRenderer());
  const LabHistory h = As("bench_3")->History("DEV-1");
  ASSERT_EQ(h.entries.size(), 2u);
  EXPECT_EQ(h.entries[0].bench, "bench_1");
  EXPECT_EQ(h.entries[1].bench, "bench_2");
}

TEST_F(LabRoles, ABenchCannotApproveWithdrawOrDelete) {
  const auto bench = As("bench_1");
  const std::string approve =
      Refused([&] { bench->SetCertificateStatus(number_, LabCertificateStatus::kApproved); });
  EXPECT_NE(approve.find("permission denied for table certificates"), std::string::npos) << approve;
  Refused([&] { bench->SetCertificateStatus(number_, LabCertificateStatus::kWithdrawn, "mine"); });
  auto raw = RawAs("bench_1");
  Refused([&] {
    raw->Exec("DELETE FROM accelcal.certificates WHERE certificate_number = $1", {PgText(number_)});
  });
  Refused([&] { raw->Exec("DELETE FROM accelcal.sessions WHERE session_uuid = $1", {PgText(uuid_)}); });
  Refused([&] {
    raw->Exec("UPDATE accelcal.calibrations SET verdict = 'PASS' WHERE session_uuid = $1", {PgText(uuid_)});
  });
  Refused([&] { raw->Exec("UPDATE accelcal.certificate_documents SET content = 'x'"); });
  Refused([&] { raw->Exec("TRUNCATE accelcal.certificates CASCADE"); });
  EXPECT_EQ(Status(number_), "issued");
}

TEST_F(LabRoles, ABenchInsertsOnlyAsItselfAndOnlyNumbersItDrew) {
  auto raw = RawAs("bench_2");
  // Another bench's name on a session: row-level security.
  const std::string as_other = Refused([&] {
    raw->Exec(
        "INSERT INTO accelcal.sessions (session_uuid, bench, name, procedure, source, operator, place, "
        "gravity, created_utc, finished_utc, accelcal_version) VALUES ($1, 'bench_1', 'x', 'p', 's', 'o', "
        "'', 'g', now(), now(), 't')",
        {PgText(NewRandomUuid())});
  });
  EXPECT_NE(as_other.find("row-level security"), std::string::npos) << as_other;
  // Parts of another bench's session.
  Refused([&] {
    raw->Exec(
        "INSERT INTO accelcal.session_equipment (session_uuid, role, equipment_id, name, uncertainty, "
        "traceability) VALUES ($1, 'level', 'L', 'l', 'u', 't')",
        {PgText(uuid_)});
  });
  // A certificate number it did not draw (its own session, a number of its choosing).
  const std::string mine = NewRandomUuid();
  As("bench_2")->Publish(MakePublication(mine, "DEV-2"), NumberedRenderer());
  const std::string forged = Refused([&] {
    raw->Exec(
        "INSERT INTO accelcal.certificates (certificate_number, seq, session_uuid, sensor_index) "
        "VALUES ('LAB-999999', 999999, $1, 1)",
        {PgText(mine)});
  });
  EXPECT_NE(forged.find("not the one this connection just drew"), std::string::npos) << forged;
  // Nor a status of its own choosing on a new certificate (no grant on the column).
  Refused([&] {
    raw->Exec(
        "INSERT INTO accelcal.certificates (certificate_number, seq, session_uuid, sensor_index, status) "
        "VALUES ('LAB-999998', 999998, $1, 1, 'approved')",
        {PgText(mine)});
  });
  // Nor the sequence itself.
  Refused([&] { raw->Exec("SELECT nextval('accelcal.certificate_seq')"); });
}

TEST_F(LabRoles, ABenchCannotKeepTheEquipmentRegisterOrTheIntervals) {
  const auto bench = As("bench_1");
  Refused([&] {
    bench->RegisterEquipment({"TT-9", "turntable", "t", "C-1", "2026-01-01", "2027-01-01", ""});
  });
  Refused([&] { bench->SetDeviceTypeInterval("X", 30); });
}

TEST_F(LabRoles, AManagerApprovesAndWithdrawsAndTheWithdrawnCertificateStays) {
  const auto manager = As(kManager);
  manager->SetCertificateStatus(number_, LabCertificateStatus::kApproved);
  EXPECT_EQ(Status(number_), "approved");
  // A withdrawal states its reason (the schema's rule).
  Refused([&] { manager->SetCertificateStatus(number_, LabCertificateStatus::kWithdrawn, " "); }, "23514");
  manager->SetCertificateStatus(number_, LabCertificateStatus::kWithdrawn,
                                "the turntable's certificate had expired");
  // Withdrawn is final.
  const std::string again =
      Refused([&] { manager->SetCertificateStatus(number_, LabCertificateStatus::kApproved); }, "23514");
  EXPECT_NE(again.find("stays withdrawn"), std::string::npos) << again;
  const LabHistory h = As("bench_2")->History("DEV-1");
  ASSERT_EQ(h.entries.size(), 1u);
  EXPECT_EQ(h.entries[0].status, "withdrawn");
  EXPECT_EQ(h.entries[0].approved_by, kManager);
  EXPECT_EQ(h.entries[0].withdrawn_by, kManager);
  EXPECT_EQ(h.entries[0].withdrawn_reason, "the turntable's certificate had expired");
  EXPECT_EQ(As(kManager)->CertificateDocuments(number_).size(), 2u);
}

TEST_F(LabRoles, NobodyDeletesACertificateNotEvenTheOwner) {
  Refused([&] {
    RawAs(kManager)->Exec("DELETE FROM accelcal.certificates WHERE certificate_number = $1",
                          {PgText(number_)});
  });
  // The owner of the tables passes every grant: the schema's trigger still refuses.
  const std::string owner = Refused([&] {
    RawAs(kAdmin)->Exec("DELETE FROM accelcal.certificates WHERE certificate_number = $1", {PgText(number_)});
  });
  EXPECT_NE(owner.find("never changed or deleted"), std::string::npos) << owner;
  Refused([&] { RawAs(kAdmin)->Exec("DELETE FROM accelcal.certificate_documents"); });
  // Only its status changes, even for a manager.
  Refused([&] {
    RawAs(kManager)->Exec("UPDATE accelcal.certificates SET session_uuid = $1 WHERE certificate_number = $2",
                          {PgText(NewRandomUuid()), PgText(number_)});
  });
  EXPECT_EQ(Status(number_), "issued");
}

TEST_F(LabRoles, AManagerWhoIsNoBenchDoesNotPublish) {
  Refused([&] { As(kManager)->Publish(MakePublication(NewRandomUuid(), "DEV-3"), NumberedRenderer()); });
  EXPECT_EQ(RawAs(kAdmin)->Exec("SELECT count(*) FROM accelcal.sessions").Int(0, 0), 1);
}

}  // namespace
}  // namespace accelcal
