// Publishing real sessions (made by accelcal_make_session, the tests' session generator): the
// number written back into the session and onto the certificate beside it, the backlog, a lost
// write-back repaired by the next publish; the equipment check the wizard's welcome makes, and how
// long the wizard waits for a lab out of reach.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <sqlite3.h>

#include "accelcal/app/lab_equipment_check.h"
#include "accelcal/app/lab_publish.h"
#include "accelcal/app/report_files.h"
#include "accelcal/app/report_metadata.h"
#include "accelcal/report/report_html.h"
#include "accelcal/report/report_text.h"
#include "lab_test_support.h"

namespace accelcal {
namespace {

namespace fs = std::filesystem;
using testing::kManager;
using testing::ScopedEnv;
using Kind = SessionPublishOutcome::Kind;

const std::string kProcedure = std::string(ACCELCAL_SOURCE_DIR) + "/procedures/full_calibration.toml";

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

class LabApp : public testing::LabDatabaseTest {
 protected:
  bool StartMigrated() const override { return true; }
  void SetUp() override {
    LabDatabaseTest::SetUp();
    dir_ = fs::temp_directory_path() / fmt::format("accelcal-lab-app-{}", database());
    fs::create_directories(dir_);
  }
  void TearDown() override {
    fs::remove_all(dir_);
    LabDatabaseTest::TearDown();
  }

  // A finished session of `device` (or one without a calibration).
  std::string MakeSession(const std::string& name, const std::string& device, bool finished = true) {
    const std::string path = (dir_ / (name + ".db")).string();
    const std::string command = fmt::format("'{}' '{}' --device '{}' {}", ACCELCAL_MAKE_SESSION, path, device,
                                            finished ? "" : "--no-result");
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return path;
  }

  static std::unique_ptr<SessionStore> Writer(const std::string& path) {
    SessionOpenOptions o;
    o.create_if_missing = false;
    return SessionStore::Open(path, o);
  }

  fs::path dir_;
};

TEST_F(LabApp, APublishedSessionHoldsTheLabsNumberAndItsCertificateBesideIt) {
  const std::string path = MakeSession("s1", "SIM-0001");
  const auto lab = As("bench_1");
  const std::vector<SessionPublishOutcome> out = PublishSessionFiles(*lab, {path}, kProcedure);
  ASSERT_EQ(out.size(), 1u);
  ASSERT_EQ(out[0].kind, Kind::kPublished) << out[0].message;
  ASSERT_EQ(out[0].certificate_numbers, std::vector<std::string>{"LAB-000001"});
  // Written back into the session, by the session's own API.
  auto store = Writer(path);
  ASSERT_EQ(store->LabCertificates().size(), 1u);
  EXPECT_EQ(store->LabCertificates()[0].certificate_number, "LAB-000001");
  EXPECT_EQ(store->LabCertificates()[0].lab, lab->Identity());
  EXPECT_EQ(store->Info().num_lab_certificates, 1);
  // The certificate beside the session is the lab's stored document, number on it.
  const std::vector<LabDocument> stored = lab->CertificateDocuments("LAB-000001");
  ASSERT_EQ(stored.size(), 2u);
  EXPECT_EQ(stored[0].media_type, "text/html");
  EXPECT_EQ(ReadFile(ReportPathFor(path, "html")), stored[0].bytes);
  EXPECT_EQ(ReadFile(ReportPathFor(path, "txt")), stored[1].bytes);
  EXPECT_NE(stored[0].bytes.find("LAB-000001"), std::string::npos);
  EXPECT_EQ(stored[0].bytes.find("ACC-s1-"), std::string::npos) << "the session's own number is gone";
  // Rendered again from the session (as `accelcal report` does), the certificate is the same bytes.
  ReportRequest request;
  request.input = path;
  request.default_procedure_path = kProcedure;
  const ReportModel again = BuildReportModel(ReportInputsFor(request));
  EXPECT_EQ(again.certificate.number, "LAB-000001");
  EXPECT_EQ(RenderReportHtml(again), stored[0].bytes);
  EXPECT_EQ(RenderReportText(again), stored[1].bytes);
  // The register knows the session by its UUID, the bench by its role.
  const LabHistory h = lab->History("SIM-0001");
  ASSERT_EQ(h.entries.size(), 1u);
  EXPECT_EQ(h.entries[0].session_uuid, store->Info().uuid);
  EXPECT_EQ(h.entries[0].session, "s1");
  EXPECT_EQ(h.entries[0].bench, "bench_1");
  EXPECT_EQ(h.entries[0].verdict, std::string(VerdictToString(again.verdict)));
}

TEST_F(LabApp, TheBacklogIsTheFinishedUnpublishedSessions) {
  const std::string a = MakeSession("20260101T000000Z", "SIM-0001");
  MakeSession("20260102T000000Z", "SIM-0002", /*finished=*/false);
  const std::string c = MakeSession("20260103T000000Z", "SIM-0003");
  EXPECT_EQ(UnpublishedSessions(dir_.string()), (std::vector<std::string>{a, c}));
  const auto lab = As("bench_1");
  PublishSessionFiles(*lab, {a}, kProcedure);
  EXPECT_EQ(UnpublishedSessions(dir_.string()), std::vector<std::string>{c});
  PublishSessionFiles(*lab, UnpublishedSessions(dir_.string()), kProcedure);
  EXPECT_TRUE(UnpublishedSessions(dir_.string()).empty());
}

// The store committed, the publisher died before writing the number back: the session is in the
// backlog still, and the next publish writes the lab's number (the same) without a second row.
TEST_F(LabApp, ALostWriteBackIsMadeByTheNextPublish) {
  const std::string path = MakeSession("s1", "SIM-0001");
  const auto lab = As("bench_1");
  PublishSessionFiles(*lab, {path}, kProcedure);
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "DELETE FROM lab_certificates", nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
  fs::remove(ReportPathFor(path, "html"));
  ASSERT_EQ(UnpublishedSessions(dir_.string()), std::vector<std::string>{path});
  const std::vector<SessionPublishOutcome> out =
      PublishSessionFiles(*lab, UnpublishedSessions(dir_.string()), kProcedure);
  ASSERT_EQ(out.at(0).kind, Kind::kAlreadyPublished) << out[0].message;
  EXPECT_EQ(out[0].certificate_numbers, std::vector<std::string>{"LAB-000001"});
  EXPECT_EQ(Writer(path)->LabCertificates().at(0).certificate_number, "LAB-000001");
  EXPECT_EQ(ReadFile(ReportPathFor(path, "html")), lab->CertificateDocuments("LAB-000001").at(0).bytes);
  EXPECT_EQ(lab->History("SIM-0001").entries.size(), 1u);
}

// A lab's number is never replaced: a session another lab's register numbered is not published
// to this one (which would then hold a session that does not carry its number).
TEST_F(LabApp, ASessionNumberedByOneLabIsNotPublishedToAnother) {
  const std::string path = MakeSession("s1", "SIM-0001");
  PublishSessionFiles(*As("bench_1"), {path}, kProcedure);
  const std::string other = database() + "_other";
  RawAs(testing::kAdmin)->ExecScript("CREATE DATABASE " + other);
  {
    ScopedEnv db("PGDATABASE", other);
    Migrate();
    const std::vector<SessionPublishOutcome> out = PublishSessionFiles(*As("bench_1"), {path}, kProcedure);
    EXPECT_EQ(out.at(0).kind, Kind::kNotReady);
    EXPECT_NE(out[0].message.find("another lab's register, as certificate LAB-000001"), std::string::npos)
        << out[0].message;
    EXPECT_EQ(RawAs(testing::kAdmin)->Exec("SELECT count(*) FROM accelcal.sessions").Int(0, 0), 0);
  }
  RawAs(testing::kAdmin)->ExecScript("DROP DATABASE " + other + " WITH (FORCE)");
}

// The wizard's end: publish when the bench is pointed at a lab; wait, never fail, when the lab
// cannot be reached; nothing at all without a lab.
TEST_F(LabApp, TheWizardsEndPublishesOnlyWhenTheBenchHasALab) {
  const std::string path = MakeSession("s1", "SIM-0001");
  auto store = Writer(path);
  {
    ScopedEnv host("PGHOST", ""), db("PGDATABASE", "");
    EXPECT_FALSE(PublishIfLabConfigured(*store, kProcedure).has_value());
  }
  {
    ScopedEnv host("PGHOST", "127.0.0.1"), port("PGPORT", "1");
    const std::optional<SessionPublishOutcome> waiting = PublishIfLabConfigured(*store, kProcedure);
    ASSERT_TRUE(waiting.has_value());
    EXPECT_EQ(waiting->kind, Kind::kFailed);
    EXPECT_TRUE(waiting->lab_unreachable);
    EXPECT_NE(waiting->message.find("it waits for `accelcal lab publish`"), std::string::npos)
        << waiting->message;
  }
  ScopedEnv user("PGUSER", "bench_1");
  const std::optional<SessionPublishOutcome> published = PublishIfLabConfigured(*store, kProcedure);
  ASSERT_TRUE(published.has_value());
  EXPECT_EQ(published->kind, Kind::kPublished) << published->message;
  EXPECT_EQ(store->LabCertificates().at(0).certificate_number, "LAB-000001");
}

TEST_F(LabApp, WhatCannotBePublishedSaysWhy) {
  const std::string open = MakeSession("open", "SIM-0001", /*finished=*/false);
  const std::string missing = (dir_ / "missing.db").string();
  const auto lab = As("bench_1");
  const std::vector<SessionPublishOutcome> out = PublishSessionFiles(*lab, {open, missing}, kProcedure);
  EXPECT_EQ(out.at(0).kind, Kind::kNotReady);
  EXPECT_NE(DescribeOutcome(out[0]).find("not finished"), std::string::npos) << DescribeOutcome(out[0]);
  EXPECT_EQ(out.at(1).kind, Kind::kFailed);
  EXPECT_NE(out[1].message.find("no session"), std::string::npos) << out[1].message;
}

// A finished session of several sensors (a fixture) is refused in plain words, before anything
// reaches the lab: never filed under the fixture's name with its first board's calibration.
TEST_F(LabApp, AFixtureSessionIsNotPublishedAndSaysWhy) {
  const std::string path = MakeSession("plate", "fixture");
  {
    Fixture plate;
    plate.sensors.resize(2);
    plate.sensors[0].serial = "BOARD-1";
    plate.sensors[1].serial = "BOARD-2";
    Writer(path)->RecordSensors(plate);
  }
  const auto lab = As("bench_1");
  const std::vector<SessionPublishOutcome> out = PublishSessionFiles(*lab, {path}, kProcedure);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].kind, Kind::kNotReady);
  EXPECT_NE(DescribeOutcome(out[0]).find("not published, a session of 2 sensors on a fixture"), std::string::npos)
      << DescribeOutcome(out[0]);
  EXPECT_TRUE(out[0].certificate_numbers.empty());
  EXPECT_TRUE(Writer(path)->LabCertificates().empty());
  EXPECT_FALSE(fs::exists(ReportPathFor(path, "html")));
}

TEST_F(LabApp, TheEquipmentCheckWarnsOfExpiredSoonAndUnknownItems) {
  const auto manager = As(kManager);
  manager->RegisterEquipment(
      {"TT-01", "turntable", "Turntable A", "C-100", "2020-01-01", "2021-01-01", "metro lab"});
  manager->RegisterEquipment({"RUL-01", "ruler", "Steel ruler", "C-200", "2026-01-01", "2099-01-01", ""});
  manager->RegisterEquipment({"LVL-01", "level", "Level", "C-300", "2020-01-01", "2020-06-01", ""});
  // A level recalibrated: its new certificate counts; the old one stays on record.
  manager->RegisterEquipment({"LVL-01", "level", "Level", "C-301", "2026-01-01", "2099-06-01", ""});
  const auto bench = As("bench_1");
  const EquipmentCheck check = CheckEquipment(*bench, {"TT-01", "RUL-01", "LVL-01", "PRISM-9", ""});
  ASSERT_EQ(check.items.size(), 4u);
  ASSERT_EQ(check.warnings.size(), 2u);
  EXPECT_NE(
      check.warnings[0].find("turntable TT-01: its calibration expired on 2021-01-01 (certificate C-100)"),
      std::string::npos)
      << check.warnings[0];
  EXPECT_NE(check.warnings[1].find("PRISM-9: not in the lab's equipment register"), std::string::npos)
      << check.warnings[1];
  EXPECT_TRUE(check.any_expired_or_unknown);
  EXPECT_EQ(check.items[2].certificate_ref, "C-301");
  // Running out soon is a warning, not a failure.
  const LabDueList due = bench->Due(30);
  bool turntable_due = false;
  for (const LabDueItem& i : due.items) turntable_due |= i.id == "TT-01" && i.days_left && *i.days_left < 0;
  EXPECT_TRUE(turntable_due);
  // Registering the same certificate again changes nothing; with other dates it is refused.
  EXPECT_NO_THROW(manager->RegisterEquipment(
      {"RUL-01", "ruler", "Steel ruler", "C-200", "2026-01-01", "2099-01-01", ""}));
  EXPECT_THROW(
      manager->RegisterEquipment({"RUL-01", "ruler", "Steel ruler", "C-200", "2026-01-01", "2098-01-01", ""}),
      Error);
}

TEST_F(LabApp, TheWelcomeChecksOnlyWhenTheBenchIsPointedAtALab) {
  std::vector<EquipmentItem> items(1);
  items[0].identification = "TT-01";
  {
    // No lab: nothing is checked, nothing waits.
    ScopedEnv host("PGHOST", ""), db("PGDATABASE", "");
    const WelcomeLabCheck none = WelcomeEquipmentWarnings(items);
    EXPECT_TRUE(none.warnings.empty());
    EXPECT_EQ(none.unreachable, "");
  }
  {
    // A lab that cannot be reached (a closed port): said, never an error, no warning of items.
    ScopedEnv host("PGHOST", "127.0.0.1"), port("PGPORT", "1");
    const WelcomeLabCheck check = WelcomeEquipmentWarnings(items);
    EXPECT_TRUE(check.warnings.empty());
    EXPECT_NE(check.unreachable.find("cannot reach the lab store"), std::string::npos) << check.unreachable;
  }
  ScopedEnv user("PGUSER", "bench_1");
  const WelcomeLabCheck check = WelcomeEquipmentWarnings(items);
  EXPECT_EQ(check.unreachable, "");
  ASSERT_EQ(check.warnings.size(), 1u);
  EXPECT_NE(check.warnings[0].find("TT-01: not in the lab's equipment register"), std::string::npos)
      << check.warnings[0];
}

// The wizard's check (WizardOptions::check_equipment): once the lab could not be reached, the
// session does not wait for it again (the welcome's equipment answer checks again): the lab is
// back here, and still not tried.
TEST_F(LabApp, TheWelcomeDoesNotWaitTwiceForALabOutOfReach) {
  std::vector<EquipmentItem> items(1);
  items[0].identification = "TT-01";
  ScopedEnv user("PGUSER", "bench_1");
  const auto check = WelcomeEquipmentCheck();
  {
    ScopedEnv host("PGHOST", "127.0.0.1"), port("PGPORT", "1");
    EXPECT_NE(check(items).unreachable, "");
  }
  const WelcomeLabCheck again = check(items);
  EXPECT_NE(again.unreachable.find("cannot reach the lab store"), std::string::npos) << again.unreachable;
  EXPECT_TRUE(again.warnings.empty());
  // A new session's check reaches it.
  EXPECT_EQ(WelcomeEquipmentCheck()(items).unreachable, "");
}

// A lab's address where something takes the connection and never answers (a wrong host behind a
// firewall or a proxy that swallows it; here a socket that listens and never accepts): the
// wizard waits kLabQuickConnectTimeoutS for it, whatever the settings say (here 60 s), then
// goes on; `accelcal lab` commands keep the settings' timeout (here 2 s, to keep the test short).
TEST_F(LabApp, ALabThatNeverAnswersHoldsTheWizardOnlyItsShortTimeout) {
  const int silent = ::socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(silent, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(silent, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(::listen(silent, 16), 0);
  socklen_t length = sizeof address;
  ASSERT_EQ(::getsockname(silent, reinterpret_cast<sockaddr*>(&address), &length), 0);
  ScopedEnv host("PGHOST", "127.0.0.1"), port("PGPORT", std::to_string(ntohs(address.sin_port)));
  const auto seconds_of = [](auto&& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  {
    ScopedEnv timeout("PGCONNECT_TIMEOUT", "60");
    std::vector<EquipmentItem> items(1);
    items[0].identification = "TT-01";
    WelcomeLabCheck check;
    const double welcome_s = seconds_of([&] { check = WelcomeEquipmentWarnings(items); });
    EXPECT_NE(check.unreachable.find("timeout expired"), std::string::npos) << check.unreachable;
    EXPECT_GE(welcome_s, kLabQuickConnectTimeoutS - 1.0);
    EXPECT_LT(welcome_s, 20.0) << "the welcome waited as the settings say, not its own short timeout";

    const std::string session = MakeSession("s1", "SIM-0001");
    auto store = Writer(session);
    std::optional<SessionPublishOutcome> end;
    const double end_s = seconds_of([&] { end = PublishIfLabConfigured(*store, kProcedure); });
    ASSERT_TRUE(end.has_value());
    EXPECT_TRUE(end->lab_unreachable) << end->message;
    EXPECT_LT(end_s, 20.0);
  }
  ScopedEnv timeout("PGCONNECT_TIMEOUT", "2");
  try {
    LabStore::Connect();
    ADD_FAILURE() << "connected to a socket that never answers";
  } catch (const LabError& e) {
    EXPECT_TRUE(e.unreachable()) << e.what();
  }
  ::close(silent);
}

}  // namespace
}  // namespace accelcal
