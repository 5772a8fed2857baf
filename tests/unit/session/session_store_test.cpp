// The SQLite session store: round trips, refusals, the lock, and durability under kill -9.
#include "accelcal/session/session_store.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include "accelcal/base/error.h"
#include "session_test_support.h"
#include "test_support.h"

namespace accelcal::session_store_test {
namespace {

namespace fs = std::filesystem;
using testing::Contains;

using SessionStoreTest = testing::SessionDirTest;

// A capture with awkward values: fractions, a NaN temperature, negative zero.
Capture MakeCapture(int id, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.3);
  Capture c;
  c.id = id;
  c.kind = id % 2 ? CaptureKind::kTurntable : CaptureKind::kStatic;
  c.label = "pose, \"" + std::to_string(id) + "\"";
  if (c.kind == CaptureKind::kTurntable) {
    c.radius_m = 0.05 + 0.001 * id;
    c.rpm = 120.0;
    c.up_axis = SensorAxis::kMinusY;
  }
  for (int k = 0; k < n; ++k) {
    Sample s;
    s.t_s = 10.0 * id + k / 100.0;
    s.raw_counts = Eigen::Vector3d(2048 + noise(rng), 2047.5 + noise(rng), k == 0 ? -0.0 : 2400 + noise(rng));
    s.temp_c = k % 3 == 0 ? kNaN : 25.0 + 0.001 * k;
    c.samples.push_back(s);
  }
  return c;
}

using accelcal::testing::SameBits;

void ExpectSameCapture(const Capture& a, const Capture& b) {
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.label, b.label);
  EXPECT_TRUE(SameBits(a.radius_m, b.radius_m) || (std::isnan(a.radius_m) && std::isnan(b.radius_m)));
  EXPECT_TRUE(SameBits(a.rpm, b.rpm) || (std::isnan(a.rpm) && std::isnan(b.rpm)));
  EXPECT_EQ(a.up_axis, b.up_axis);
  EXPECT_EQ(a.rejection_reason, b.rejection_reason);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  for (size_t i = 0; i < a.samples.size(); ++i) {
    EXPECT_TRUE(SameBits(a.samples[i].t_s, b.samples[i].t_s));
    for (int j = 0; j < 3; ++j)
      EXPECT_TRUE(SameBits(a.samples[i].raw_counts(j), b.samples[i].raw_counts(j))) << i << " " << j;
    EXPECT_TRUE(SameBits(a.samples[i].temp_c, b.samples[i].temp_c)) << i;
  }
}

// Schema version 3 names the capture statistics' second moments for what they hold (versions 1
// and 2 stored the same co-moment sums as cov_*): a version-2 file is read as it is and
// migrated by a writer, values unchanged.
TEST_F(SessionStoreTest, AVersionTwoSessionGetsTheCoMomentColumnsRenamedByAWriter) {
  const Capture capture = MakeCapture(1, 200, 7);
  {
    auto store = SessionStore::Open(path_, Writer());
    store->RecordCapture("face_1", capture);
  }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path_.c_str(), &db), SQLITE_OK);
  std::string sql = "PRAGMA user_version = 2;";
  for (const char* c : {"xx", "xy", "xz", "yy", "yz", "zz"})
    sql += std::string(" ALTER TABLE captures RENAME COLUMN comoment_") + c + "_counts2 TO cov_" + c + "_counts2;";
  ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
  ExpectSameCapture(SessionStore::Open(path_, Reader())->Captures().at(0).capture, capture);
  SessionStore::Open(path_, Writer());  // migrates
  ASSERT_EQ(sqlite3_open(path_.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* st = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, "SELECT comoment_xx_counts2, n FROM captures", -1, &st, nullptr), SQLITE_OK);
  ASSERT_EQ(sqlite3_step(st), SQLITE_ROW);
  EXPECT_DOUBLE_EQ(sqlite3_column_double(st, 0), capture.stats().comoment_counts2(0, 0));
  sqlite3_finalize(st);
  ASSERT_EQ(sqlite3_prepare_v2(db, "PRAGMA user_version", -1, &st, nullptr), SQLITE_OK);
  ASSERT_EQ(sqlite3_step(st), SQLITE_ROW);
  // The current version (4 added checksums, 5 redo, 6 lab identity, 7 several sensors).
  EXPECT_EQ(sqlite3_column_int64(st, 0), 7);
  sqlite3_finalize(st);
  sqlite3_close(db);
  ExpectSameCapture(SessionStore::Open(path_, Reader())->Captures().at(0).capture, capture);
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

// Version 5 keeps a capture taken again (a redo) marked superseded. A version-4 session made by
// accelcal at de59c6d (tests/data/session/README.md) is read as it is, migrated by a writer, and
// takes a redo that supersedes its first capture; the mark survives a reopen and the checksums
// still hold.
TEST_F(SessionStoreTest, AVersionFourSessionIsMigratedAndTakesARedo) {
  fs::copy_file(std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/session/v4_two_poses.db", path_);
  ASSERT_EQ(UserVersion(path_), 4);
  {
    const std::vector<JournalCapture> before = SessionStore::Open(path_, Reader())->Captures();
    ASSERT_EQ(before.size(), 2u);
    EXPECT_FALSE(before[0].superseded());
    EXPECT_FALSE(before[1].superseded());
  }
  const Capture redo = MakeCapture(3, 120, 9);
  {
    auto store = SessionStore::Open(path_, Writer());  // migrates
    store->RecordRedoCapture("pose_pz#2", redo, "pose_pz");
  }
  EXPECT_EQ(UserVersion(path_), 7);
  auto store = SessionStore::Open(path_, Reader());
  EXPECT_TRUE(store->DamagedCaptures().empty());
  const std::vector<JournalCapture> all = store->Captures();
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].step_id, "pose_pz");
  EXPECT_EQ(all[0].superseded_by, "pose_pz#2");
  EXPECT_EQ(all[0].capture.samples.size(), 100u);  // kept as it was
  EXPECT_FALSE(all[1].superseded());
  EXPECT_EQ(all[2].step_id, "pose_pz#2");
  ExpectSameCapture(all[2].capture, redo);
  const std::vector<JournalCapture> current = CurrentCaptures(all);
  ASSERT_EQ(current.size(), 2u);
  EXPECT_EQ(current[0].step_id, "pose_mz");
  EXPECT_EQ(current[1].step_id, "pose_pz#2");
}

TEST_F(SessionStoreTest, ARedoOfNothingOrOfASupersededCaptureIsRefusedAndChangesNothing) {
  auto store = SessionStore::Open(path_, Writer());
  store->RecordCapture("face_1", MakeCapture(1, 50, 1));
  try {
    store->RecordRedoCapture("face_2#2", MakeCapture(2, 50, 2), "face_2");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "step 'face_2' has no capture to supersede")) << e.what();
  }
  store->RecordRedoCapture("face_1#2", MakeCapture(2, 50, 2), "face_1");
  try {
    store->RecordRedoCapture("face_1#3", MakeCapture(3, 50, 3), "face_1");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "already superseded by 'face_1#2'")) << e.what();
  }
  // The new capture's step id taken: the old one is not marked (one transaction).
  store->RecordCapture("face_3", MakeCapture(4, 50, 4));
  EXPECT_THROW(store->RecordRedoCapture("face_3", MakeCapture(5, 50, 5), "face_1#2"), Error);
  const std::vector<JournalCapture> all = store->Captures();
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].superseded_by, "face_1#2");
  EXPECT_FALSE(all[1].superseded());
  EXPECT_FALSE(all[2].superseded());
}

TEST(MemoryJournalTest, ARedoSupersedesTheOldCaptureAndRefusesWhatTheStoreRefuses) {
  std::unique_ptr<SessionJournal> journal = MakeMemoryJournal();
  journal->RecordCapture("face_1", MakeCapture(1, 20, 1));
  EXPECT_THROW(journal->RecordRedoCapture("face_2#2", MakeCapture(2, 20, 2), "face_2"), Error);
  journal->RecordRedoCapture("face_1#2", MakeCapture(2, 20, 2), "face_1");
  EXPECT_THROW(journal->RecordRedoCapture("face_1#3", MakeCapture(3, 20, 3), "face_1"), Error);
  const std::vector<JournalCapture> all = journal->Captures();
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].superseded_by, "face_1#2");
  EXPECT_EQ(CurrentCaptures(all).size(), 1u);
}

TEST_F(SessionStoreTest, RoundTripsEverythingThroughAReopen) {
  const Capture first = MakeCapture(1, 500, 1);
  Capture second = MakeCapture(2, 300, 2);
  second.rejection_reason = "not still: moving";
  const std::string result = R"({"format": "accelcal-calibration/1", "x": 0.30000000000000004})";
  {
    auto store = SessionStore::Open(path_, Writer());
    store->RecordInput("session", "device", "SN-42");
    store->RecordInput("session", "operator", "Ada");
    store->RecordInput("mount", "radius_m", "0.05");
    store->RecordInput("mount", "radius_m", "0.051");  // replaces
    store->RecordCapture("face_1", first);
    store->RecordStepDone("level", "leveled");
    store->RecordCapture("table_1", second);
    store->RecordResult(result);
    store->MarkDone();
  }
  auto store = SessionStore::Open(path_, Reader());
  const std::vector<JournalCapture> captures = store->Captures();
  ASSERT_EQ(captures.size(), 2u);
  EXPECT_EQ(captures[0].step_id, "face_1");
  EXPECT_EQ(captures[1].step_id, "table_1");
  ExpectSameCapture(captures[0].capture, first);
  ExpectSameCapture(captures[1].capture, second);
  EXPECT_EQ(store->Inputs().at("mount").at("radius_m"), "0.051");
  EXPECT_EQ(store->Inputs().at("session").at("device"), "SN-42");
  EXPECT_EQ(store->DoneSteps().at("level"), "leveled");
  ASSERT_TRUE(store->Result().has_value());
  EXPECT_EQ(*store->Result(), result);
  const SessionInfo info = store->Info();
  EXPECT_EQ(info.name, "s");
  EXPECT_EQ(info.procedure, "bench_default");
  EXPECT_EQ(info.source, "sim");
  EXPECT_EQ(info.device, "SN-42");
  EXPECT_EQ(info.operator_name, "Ada");
  EXPECT_EQ(info.state, SessionState::kDone);
  EXPECT_EQ(info.num_captures, 2);
  EXPECT_EQ(info.num_inputs, 3);
  EXPECT_EQ(info.num_done_steps, 1);
  EXPECT_TRUE(info.has_result);
  EXPECT_FALSE(info.created_utc.empty());
  EXPECT_GE(info.updated_utc, info.created_utc);
}

TEST_F(SessionStoreTest, ASecondCaptureForAStepIsRefusedAndChangesNothing) {
  auto store = SessionStore::Open(path_, Writer());
  store->RecordCapture("face_1", MakeCapture(1, 50, 1));
  try {
    store->RecordCapture("face_1", MakeCapture(7, 60, 2));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "step 'face_1' already has an accepted capture")) << e.what();
  }
  const std::vector<JournalCapture> captures = store->Captures();
  ASSERT_EQ(captures.size(), 1u);
  EXPECT_EQ(captures[0].capture.id, 1);
  EXPECT_EQ(captures[0].capture.samples.size(), 50u);
  store->RecordCapture("face_2", MakeCapture(2, 10, 3));  // the store still works
  EXPECT_EQ(store->Captures().size(), 2u);
}

TEST_F(SessionStoreTest, RefusesANewerSchemaAndForeignFiles) {
  SessionStore::Open(path_, Writer()).reset();
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path_.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "PRAGMA user_version = 99", nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
  try {
    SessionStore::Open(path_, Reader());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "schema version 99, newer than this accelcal reads (7)")) << e.what();
  }
  const std::string text_file = (dir_ / "notes.db").string();
  { std::ofstream(text_file) << "this is not a database, just text long enough to be read\n"; }
  try {
    SessionStore::Open(text_file, Writer());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "is not an accelcal session")) << e.what();
  }
  EXPECT_THROW(SessionStore::Open((dir_ / "missing.db").string(), Reader()), Error);
}

TEST_F(SessionStoreTest, ReadOnlyOpenCannotWrite) {
  SessionStore::Open(path_, Writer()).reset();
  auto store = SessionStore::Open(path_, Reader());
  EXPECT_THROW(store->RecordStepDone("x", "done"), Error);
}

// Runs `fn` in a child process; returns its exit status (or 128 + signal).
template <typename Fn>
int InChild(Fn&& fn) {
  const pid_t pid = fork();
  if (pid == 0) _exit(fn());
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST_F(SessionStoreTest, ASecondWriterIsRefusedWithThePidAndReadersStillWork) {
  auto store = SessionStore::Open(path_, Writer());
  store->RecordCapture("face_1", MakeCapture(1, 20, 1));
  const std::string pid = std::to_string(getpid());
  const std::string want = "session " + path_ + " is open in another accelcal (pid " + pid + ")";
  const int status = InChild([&] {
    try {
      SessionStore::Open(path_, Writer());
      return 2;
    } catch (const Error& e) {
      if (std::string(e.what()) != want) return 3;
    }
    try {
      return SessionStore::Open(path_, Reader())->Captures().size() == 1 ? 0 : 4;
    } catch (const Error&) {
      return 5;
    }
  });
  EXPECT_EQ(status, 0) << "2: not refused, 3: wrong message, 4/5: reader failed";
  // Within one process, too (flock is per open file).
  EXPECT_THROW(SessionStore::Open(path_, Writer()), Error);
}

TEST_F(SessionStoreTest, TheLockDiesWithItsHolder) {
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t pid = fork();
  if (pid == 0) {
    auto store = SessionStore::Open(path_, Writer());
    store->RecordStepDone("level", "leveled");
    char c = 1;
    if (write(ready[1], &c, 1) != 1) _exit(1);
    pause();  // holds the lock until killed
    _exit(0);
  }
  char c = 0;
  ASSERT_EQ(read(ready[0], &c, 1), 1);
  EXPECT_THROW(SessionStore::Open(path_, Writer()), Error);
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  close(ready[0]);
  close(ready[1]);
  auto store = SessionStore::Open(path_, Writer());  // the stale lock file does not block
  EXPECT_EQ(store->DoneSteps().at("level"), "leveled");
}

// The child records captures in a loop from `first_step`, reporting each step id on `fd` only
// after RecordCapture returned (so whatever the parent read must be in the store).
[[noreturn]] void RecordForever(const std::string& path, int first_step, int fd) {
  SessionOpenOptions o;
  auto store = SessionStore::Open(path, o);
  for (int step = first_step;; ++step) {
    store->RecordCapture("step_" + std::to_string(step), MakeCapture(step, 1000, static_cast<unsigned>(step)));
    const std::string line = std::to_string(step) + "\n";
    if (write(fd, line.data(), line.size()) < 0) _exit(1);
  }
}

// The statistics columns agree with the samples: n, mean and time range of every row.
void ExpectStoredStatsMatchSamples(const std::string& path) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  sqlite3_stmt* row = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, "SELECT capture_id, n, mean_x_counts, mean_z_counts, t_last_s "
                                   "FROM captures", -1, &row, nullptr), SQLITE_OK);
  while (sqlite3_step(row) == SQLITE_ROW) {
    const int id = sqlite3_column_int(row, 0);
    const CaptureStats stats = ComputeStats(MakeCapture(id, 1000, static_cast<unsigned>(id)).samples);
    EXPECT_EQ(sqlite3_column_int64(row, 1), 1000) << id;
    EXPECT_EQ(sqlite3_column_double(row, 2), stats.mean_counts.x()) << id;
    EXPECT_EQ(sqlite3_column_double(row, 3), stats.mean_counts.z()) << id;
    EXPECT_EQ(sqlite3_column_double(row, 4), stats.t_last_s) << id;
  }
  sqlite3_finalize(row);
  sqlite3_close(db);
}

TEST_F(SessionStoreTest, KillNineAtRandomInstantsLosesNothingCommitted) {
  std::mt19937 rng(20240601);
  std::uniform_int_distribution<int> delay_us(0, 60000);
  std::set<long> committed;  // every step a child reported
  // Opens after a kill (no stale lock) and checks: every capture whole, no step twice, every
  // reported step there. Returns the next step to record.
  auto check = [&]() {
    int next_step = 1;
    auto store = SessionStore::Open(path_, Writer());
    std::set<std::string> seen;
    for (const JournalCapture& c : store->Captures()) {
      EXPECT_TRUE(seen.insert(c.step_id).second) << "duplicate " << c.step_id;
      EXPECT_EQ(c.capture.samples.size(), 1000u) << c.step_id;
      ExpectSameCapture(c.capture, MakeCapture(c.capture.id, 1000, static_cast<unsigned>(c.capture.id)));
      next_step = std::max(next_step, c.capture.id + 1);
    }
    for (long step : committed) EXPECT_TRUE(seen.count("step_" + std::to_string(step))) << "lost " << step;
    ExpectStoredStatsMatchSamples(path_);
    return next_step;
  };
  for (int round = 0; round < 20; ++round) {
    const int next_step = check();
    if (::testing::Test::HasFailure()) return;
    // Every other round the kill comes at a random instant after the child's first commit, so
    // the children make progress however slow a loaded machine makes them; the other rounds
    // also hit the open and the first transaction.
    const std::set<long> reported = testing::RunAndKill(
        [&](int fd) { RecordForever(path_, next_step, fd); }, delay_us(rng), round % 2 == 0);
    committed.insert(reported.begin(), reported.end());
  }
  check();
  EXPECT_GE(committed.size(), 10u) << "the children hardly recorded anything; the test proves little";
}

}  // namespace
}  // namespace accelcal::session_store_test
