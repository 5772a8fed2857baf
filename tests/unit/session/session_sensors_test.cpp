// Several sensors in one session (schema version 7, issue 31): each capture names its sensor,
// a pose's captures of every sensor are one transaction (kill -9 keeps all or none), the
// session's sensors round-trip, and older one-sensor sessions open as they were and migrate
// (their captures sensor 0's, their checksums holding, a damaged row still damaged).
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include "accelcal/base/error.h"
#include "accelcal/base/fixture.h"
#include "accelcal/session/sensor_journal_view.h"
#include "accelcal/session/session_store.h"
#include "session_test_support.h"
#include "test_support.h"

namespace accelcal::session_sensors_test {
namespace {

namespace fs = std::filesystem;
using SessionSensorsTest = testing::SessionDirTest;

Capture Pose(int id, double level) {
  Capture c;
  c.id = id;
  c.label = "pose " + std::to_string(id);
  for (int k = 0; k < 20; ++k) {
    Sample s;
    s.t_s = id * 10.0 + k * 0.01;
    s.raw_counts = Eigen::Vector3d(level + k % 3, -level, 2.0 * level);
    c.samples.push_back(s);
  }
  return c;
}

Fixture ThreeBoards() {
  Fixture f;
  f.name = "plate A";
  for (const char* serial : {"B1", "B2", "B3"}) {
    FixtureSensor s;
    s.serial = serial;
    f.sensors.push_back(s);
  }
  f.sensors[1].sensor_to_plate = SensorToPlate(SensorAxis::kPlusY, SensorAxis::kMinusX);
  f.sensors[2].offset_m = Eigen::Vector3d(0.0125, -0.03, 0.1);
  f.sensors[2].source = "serial:/dev/ttyUSB2@115200";
  return f;
}

void Exec(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  char* error = nullptr;
  EXPECT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error), SQLITE_OK) << error;
  sqlite3_free(error);
  sqlite3_close(db);
}

TEST_F(SessionSensorsTest, EachSensorsCapturesAndTheSensorsRoundTrip) {
  {
    auto store = SessionStore::Open(path_, Writer());
    store->RecordSensors(ThreeBoards());
    store->RecordSensors(ThreeBoards());  // a resume: the same again is a no-op
    store->RecordSensorCaptures("pose_pz", {{0, Pose(1, 100)}, {1, Pose(1, 200)}, {2, Pose(1, 300)}});
    // A pose the second board missed (left out of it): the others' only.
    store->RecordSensorCaptures("pose_mz", {{0, Pose(2, 110)}, {2, Pose(2, 310)}});
  }
  auto store = SessionStore::Open(path_, Reader());
  const std::optional<Fixture> sensors = store->Sensors();
  ASSERT_TRUE(sensors.has_value());
  ASSERT_EQ(sensors->sensors.size(), 3u);
  EXPECT_EQ(sensors->name, "plate A");
  EXPECT_EQ(sensors->sensors[1].serial, "B2");
  EXPECT_EQ(sensors->sensors[1].sensor_to_plate, ThreeBoards().sensors[1].sensor_to_plate);
  EXPECT_EQ(sensors->sensors[2].offset_m, ThreeBoards().sensors[2].offset_m);  // exactly
  EXPECT_EQ(sensors->sensors[2].source, "serial:/dev/ttyUSB2@115200");
  ASSERT_EQ(store->SensorCaptures(1).size(), 1u);
  EXPECT_EQ(store->SensorCaptures(1)[0].sensor, 1);
  EXPECT_EQ(store->SensorCaptures(1)[0].capture.samples[0].raw_counts.x(), 200.0);
  ASSERT_EQ(store->SensorCaptures(2).size(), 2u);
  EXPECT_EQ(store->SensorCaptures(2)[1].step_id, "pose_mz");
  EXPECT_TRUE(store->SensorCaptures(3).empty());
  // Captures() is the first sensor's: every reader of a one-sensor session reads it as before.
  ASSERT_EQ(store->Captures().size(), 2u);
  EXPECT_EQ(store->Captures()[1].capture.samples[0].raw_counts.x(), 110.0);
  EXPECT_EQ(store->Info().num_captures, 2);  // poses
  EXPECT_EQ(SessionSensors(*store).sensors[2].serial, "B3");
}

TEST_F(SessionSensorsTest, ThePlatesPlacementUncertaintyIsKeptWithTheSensors) {
  Fixture stated = ThreeBoards();
  stated.placement_u_rad = 0.1 * M_PI / 180.0;
  {
    auto store = SessionStore::Open(path_, Writer());
    store->RecordSensors(stated);
    store->RecordSensors(stated);  // a resume
    // The same boards with another figure are other sensors: a session's never change.
    EXPECT_THROW(store->RecordSensors(ThreeBoards()), Error);
  }
  auto store = SessionStore::Open(path_, Reader());
  EXPECT_DOUBLE_EQ(store->Sensors()->placement_u_rad, stated.placement_u_rad);
  // Not stated: not stated when read back (no figure invented).
  const std::string other = path_ + ".other.db";
  {
    auto unstated = SessionStore::Open(other, Writer());
    unstated->RecordSensors(ThreeBoards());
  }
  EXPECT_TRUE(std::isnan(SessionStore::Open(other, Reader())->Sensors()->placement_u_rad));
  fs::remove(other);
}

TEST_F(SessionSensorsTest, AStepOncePerSensorAndAPoseIsAllOrNothing) {
  auto store = SessionStore::Open(path_, Writer());
  store->RecordSensors(ThreeBoards());
  store->RecordSensorCaptures("pose_pz", {{0, Pose(1, 100)}, {1, Pose(1, 200)}});
  // Board 3's capture of the same pose later (a retry of it alone) is its own.
  store->RecordSensorCaptures("pose_pz", {{2, Pose(1, 300)}});
  // A second capture of a sensor for the step: refused, and the pose's other captures with it.
  EXPECT_THROW(store->RecordSensorCaptures("pose_px", {{0, Pose(2, 1)}, {1, Pose(2, 2)}, {1, Pose(2, 3)}}),
               Error);
  EXPECT_THROW(store->RecordSensorCaptures("pose_pz", {{1, Pose(3, 1)}}), Error);
  EXPECT_THROW(store->RecordSensorCaptures("pose_py", {{3, Pose(3, 1)}}), Error);  // no 4th
  for (int i = 0; i < 3; ++i) EXPECT_EQ(store->SensorCaptures(i).size(), 1u) << i;
  // The sensors never change under the captures.
  Fixture other = ThreeBoards();
  other.sensors[0].serial = "X";
  EXPECT_THROW(store->RecordSensors(other), Error);
}

TEST_F(SessionSensorsTest, AOneSensorSessionIsItsDevicesOneSensor) {
  auto store = SessionStore::Open(path_, Writer());
  store->RecordInput(kSessionStep, kDeviceKey, "SN-7");
  store->RecordCapture("pose_pz", Pose(1, 5));
  EXPECT_FALSE(store->Sensors().has_value());
  const Fixture one = SessionSensors(*store);
  ASSERT_EQ(one.sensors.size(), 1u);
  EXPECT_EQ(one.sensors[0].serial, "SN-7");
  EXPECT_EQ(store->SensorCaptures(0).size(), 1u);
  // A second sensor's capture needs the session's sensors first.
  EXPECT_THROW(store->RecordSensorCaptures("pose_mz", {{1, Pose(2, 5)}}), Error);
}

// Kill -9 between poses: every pose whose commit returned is there for every sensor, and no pose
// is there for some sensors only.
TEST_F(SessionSensorsTest, KillNineKeepsEveryCommittedPoseOfEverySensor) {
  {
    auto store = SessionStore::Open(path_, Writer());
    store->RecordSensors(ThreeBoards());
  }
  const std::string path = path_;
  const std::set<long> reported = testing::RunAndKill(
      [path](int fd) {
        auto store = SessionStore::Open(path, SessionDirTest::Writer());
        for (long i = 0;; ++i) {
          const std::string step = "pose_" + std::to_string(i);
          store->RecordSensorCaptures(step, {{0, Pose(1, i)}, {1, Pose(1, i)}, {2, Pose(1, i)}});
          const std::string line = std::to_string(i) + "\n";
          if (write(fd, line.data(), line.size()) < 0) return;
        }
      },
      150000, true);
  ASSERT_FALSE(reported.empty());
  auto store = SessionStore::Open(path_, Reader());
  const std::size_t poses = store->SensorCaptures(0).size();
  EXPECT_GE(poses, reported.size());
  for (int i = 1; i < 3; ++i) EXPECT_EQ(store->SensorCaptures(i).size(), poses) << i;
  EXPECT_TRUE(store->DamagedCaptures().empty());
}

std::int64_t UserVersion(const std::string& path) {
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* st = nullptr;
  EXPECT_EQ(sqlite3_prepare_v2(db, "PRAGMA user_version", -1, &st, nullptr), SQLITE_OK);
  EXPECT_EQ(sqlite3_step(st), SQLITE_ROW);
  const std::int64_t version = sqlite3_column_int64(st, 0);
  sqlite3_finalize(st);
  sqlite3_close(db);
  return version;
}

// A version-4 session written by an older accelcal (tests/data/session/README.md): read as it
// is, then migrated by a writer into version 7; its captures are sensor 0's, its checksums
// hold, and it takes a second sensor only after its sensors are recorded.
TEST_F(SessionSensorsTest, AnOlderOneSensorSessionOpensAndMigrates) {
  fs::copy_file(std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/session/v4_two_poses.db", path_);
  ASSERT_EQ(UserVersion(path_), 4);
  std::vector<JournalCapture> before;
  {
    auto reader = SessionStore::Open(path_, Reader());
    before = reader->Captures();
    ASSERT_EQ(before.size(), 2u);
    EXPECT_FALSE(reader->Sensors().has_value());
    EXPECT_TRUE(reader->SensorCaptures(1).empty());
  }
  {
    auto store = SessionStore::Open(path_, Writer());  // migrates
    const std::vector<JournalCapture> after = store->Captures();
    ASSERT_EQ(after.size(), 2u);
    for (size_t i = 0; i < after.size(); ++i) {
      EXPECT_EQ(after[i].step_id, before[i].step_id);
      EXPECT_EQ(after[i].sensor, 0);
      EXPECT_EQ(after[i].capture.samples.size(), before[i].capture.samples.size());
      EXPECT_EQ(after[i].capture.samples.back().raw_counts, before[i].capture.samples.back().raw_counts);
    }
    EXPECT_TRUE(store->DamagedCaptures().empty());
    Fixture two;
    two.sensors.resize(2);
    two.sensors[0].serial = "old";
    two.sensors[1].serial = "new";
    store->RecordSensors(two);
    store->RecordSensorCaptures("pose_pz", {{1, Pose(7, 1)}});  // the step again, sensor 2
  }
  EXPECT_EQ(UserVersion(path_), 7);
  auto store = SessionStore::Open(path_, Reader());
  EXPECT_EQ(store->Captures().size(), 2u);
  EXPECT_EQ(store->SensorCaptures(1).size(), 1u);
  EXPECT_TRUE(store->DamagedCaptures().empty());
}

// A version-6 session as lab-store's accelcal leaves it (its UUID, its lab number; captures with
// step_id UNIQUE and no sensor): the v4 file taken through that build's own version-6 steps, as
// SQL, with a result and a published number. Read as it is, then migrated to 7 by a writer:
// its identity, its number, its captures (sensor 0's, checksums holding) and its result kept.
TEST_F(SessionSensorsTest, ALabStoreVersionSixSessionOpensAndMigratesKeepingItsIdentity) {
  fs::copy_file(std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/session/v4_two_poses.db", path_);
  const std::string uuid = "3f2b8c1e-9d4a-4e6b-8f0c-2a5d7e9b1c34";
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path_.c_str(), &db), SQLITE_OK);
    const std::string lab_v6 =
        "BEGIN; ALTER TABLE captures ADD COLUMN superseded_by TEXT; "
        "ALTER TABLE session ADD COLUMN uuid TEXT; UPDATE session SET uuid = '" + uuid + "'; "
        "CREATE TABLE lab_certificates (sensor_index INTEGER PRIMARY KEY CHECK (sensor_index >= 0), "
        "certificate_number TEXT NOT NULL, lab TEXT NOT NULL, published_utc TEXT NOT NULL); "
        "INSERT INTO lab_certificates VALUES (0, 'LAB-000007', 'lab 1234 (database lab)', "
        "'2026-11-27T08:00:00.000Z'); "
        "INSERT INTO results (calibration_json, recorded_utc) VALUES ('{\"a\":1}', '2026-11-27T07:00:00.000Z'); "
        "PRAGMA user_version = 6; COMMIT;";
    char* error = nullptr;
    ASSERT_EQ(sqlite3_exec(db, lab_v6.c_str(), nullptr, nullptr, &error), SQLITE_OK) << (error ? error : "");
    sqlite3_close(db);
  }
  ASSERT_EQ(UserVersion(path_), 6);
  std::vector<JournalCapture> before;
  {
    auto reader = SessionStore::Open(path_, Reader());  // as it is
    before = reader->Captures();
    ASSERT_EQ(before.size(), 2u);
    EXPECT_TRUE(reader->DamagedCaptures().empty());
    EXPECT_EQ(reader->Info().uuid, uuid);
    EXPECT_EQ(reader->Info().num_lab_certificates, 1);
    EXPECT_FALSE(reader->Sensors().has_value());
    EXPECT_EQ(reader->ResultCount(), 1);
    EXPECT_EQ(reader->SensorResultCount(1), 0);
  }
  EXPECT_EQ(UserVersion(path_), 6);  // a reader changes nothing
  {
    auto store = SessionStore::Open(path_, Writer());  // migrates
    EXPECT_EQ(store->Info().uuid, uuid);
    store->RecordSensorResult(0, "{\"a\":2}");
  }
  EXPECT_EQ(UserVersion(path_), 7);
  auto store = SessionStore::Open(path_, Reader());
  EXPECT_EQ(store->Info().uuid, uuid);
  ASSERT_EQ(store->LabCertificates().size(), 1u);
  EXPECT_EQ(store->LabCertificates()[0].certificate_number, "LAB-000007");
  const std::vector<JournalCapture> after = store->Captures();
  ASSERT_EQ(after.size(), before.size());
  for (size_t i = 0; i < after.size(); ++i) {
    EXPECT_EQ(after[i].step_id, before[i].step_id);
    EXPECT_EQ(after[i].sensor, 0);
    EXPECT_EQ(after[i].capture.samples.size(), before[i].capture.samples.size());
  }
  EXPECT_TRUE(store->DamagedCaptures().empty());
  EXPECT_EQ(store->ResultCount(), 2);  // the lab build's result is sensor 0's
  EXPECT_EQ(*store->Result(), "{\"a\":2}");
}

// A row damaged before the migration stays damaged after it (the new checksum never blesses it).
TEST_F(SessionSensorsTest, TheMigrationKeepsADamagedRowDamaged) {
  fs::copy_file(std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/session/v4_two_poses.db", path_);
  Exec(path_, "UPDATE captures SET label = 'tampered' WHERE step_id = 'pose_mz'");
  ASSERT_EQ(SessionStore::Open(path_, Reader())->DamagedCaptures().size(), 1u);
  SessionStore::Open(path_, Writer());  // migrates
  auto store = SessionStore::Open(path_, Reader());
  ASSERT_EQ(store->DamagedCaptures().size(), 1u);
  EXPECT_EQ(store->DamagedCaptures()[0].step_id, "pose_mz");
  ASSERT_EQ(store->Captures().size(), 1u);
  EXPECT_EQ(store->Captures()[0].step_id, "pose_pz");
}

// The sensor is under the checksum: a row moved to another sensor is damage, named with it.
TEST_F(SessionSensorsTest, ACaptureMovedToAnotherSensorIsCaughtAsDamage) {
  {
    auto store = SessionStore::Open(path_, Writer());
    store->RecordSensors(ThreeBoards());
    store->RecordSensorCaptures("pose_pz", {{0, Pose(1, 1)}, {1, Pose(1, 2)}});
  }
  Exec(path_, "UPDATE captures SET sensor = 2 WHERE sensor = 1");
  auto store = SessionStore::Open(path_, Reader());
  ASSERT_EQ(store->DamagedCaptures().size(), 1u);
  EXPECT_NE(store->DamagedCaptures()[0].Describe().find("of sensor 3"), std::string::npos)
      << store->DamagedCaptures()[0].Describe();
  EXPECT_TRUE(store->SensorCaptures(2).empty());
}

TEST(MemoryJournalSensors, HoldsEachSensorsCapturesAsTheStoreDoes) {
  std::unique_ptr<SessionJournal> journal = MakeMemoryJournal();
  journal->RecordSensors(ThreeBoards());
  journal->RecordSensorCaptures("pose_pz", {{0, Pose(1, 1)}, {2, Pose(1, 3)}});
  EXPECT_THROW(journal->RecordSensorCaptures("pose_pz", {{1, Pose(1, 2)}, {2, Pose(1, 3)}}), Error);
  EXPECT_EQ(journal->SensorCaptures(1).size(), 0u);  // nothing of the refused pose
  EXPECT_EQ(journal->Captures().size(), 1u);
  EXPECT_EQ(journal->SensorCaptures(2).size(), 1u);
}

// Each fit round records one result per sensor: a sensor's count of results (its history, what
// its report's "earlier calibrations" says) is its own, in the store, the memory journal and a
// sensor's view alike.
TEST_F(SessionSensorsTest, EachSensorCountsItsOwnResults) {
  std::unique_ptr<SessionJournal> memory = MakeMemoryJournal();
  std::unique_ptr<SessionStore> store = SessionStore::Open(path_, Writer());
  for (SessionJournal* j : {memory.get(), static_cast<SessionJournal*>(store.get())}) {
    j->RecordSensors(ThreeBoards());
    for (int round = 0; round < 2; ++round)
      for (int sensor = 0; sensor < 3; ++sensor) j->RecordSensorResult(sensor, "{}");
    j->RecordSensorResult(2, "{\"again\":1}");
    EXPECT_EQ(j->ResultCount(), 2);
    EXPECT_EQ(j->SensorResultCount(1), 2);
    EXPECT_EQ(j->SensorResultCount(2), 3);
    EXPECT_EQ(SensorJournalView(*j, 2).ResultCount(), 3);
    EXPECT_EQ(*SensorJournalView(*j, 2).Result(), "{\"again\":1}");
  }
}

// A record step is the lead's (the wizard drives the lead alone): its records are seen through
// the sensor that led, not through the first sensor, whoever that is.
TEST(SessionSensors, TheRecordsAreTheLeadsSensors) {
  std::unique_ptr<SessionJournal> j = MakeMemoryJournal();
  j->RecordSensors(ThreeBoards());
  RecordChunk chunk;
  chunk.samples = {Sample{0.0, Eigen::Vector3d(1, 2, 3)}, Sample{0.01, Eigen::Vector3d(1, 2, 4)}};
  j->AppendRecordChunk("noise", chunk);
  EXPECT_EQ(SensorJournalView(*j, 0).RecordSteps().size(), 1u);  // no lead recorded: the first
  j->RecordInput(kSensorSetStep, kSensorSetLeadKey, "B2");
  EXPECT_TRUE(SensorJournalView(*j, 0).RecordSteps().empty());
  EXPECT_EQ(SensorJournalView(*j, 0).RecordSummaryOf("noise").num_chunks, 0);
  ASSERT_EQ(SensorJournalView(*j, 1).RecordSteps(), std::vector<std::string>{"noise"});
  EXPECT_EQ(SensorJournalView(*j, 1).RecordSummaryOf("noise").num_chunks, 1);
  long seen = 0;
  SensorJournalView(*j, 2).VisitRecordChunks("noise", [&](const RecordChunk&) { ++seen; });
  EXPECT_EQ(seen, 0);
  // Another sensor's record of the step, under its own id: seen through its view only.
  chunk.samples[0].raw_counts.x() = 7.0;
  j->AppendRecordChunk(SensorRecordStep("noise", "B3"), chunk);
  ASSERT_EQ(SensorJournalView(*j, 2).RecordSteps(), std::vector<std::string>{"noise"});
  SensorJournalView(*j, 2).VisitRecordChunks("noise", [&](const RecordChunk& c) {
    ++seen;
    EXPECT_EQ(c.samples[0].raw_counts.x(), 7.0);
  });
  EXPECT_EQ(seen, 1);
  ASSERT_EQ(SensorJournalView(*j, 1).RecordSteps(), std::vector<std::string>{"noise"});  // the lead's
  SensorJournalView(*j, 1).VisitRecordChunks("noise", [&](const RecordChunk& c) {
    EXPECT_EQ(c.samples[0].raw_counts.x(), 1.0);
  });
  EXPECT_TRUE(SensorJournalView(*j, 0).RecordSteps().empty());
}

}  // namespace
}  // namespace accelcal::session_sensors_test
