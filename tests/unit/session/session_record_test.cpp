// Record chunks and gaps in the session store and the memory journal: round trips, refusals,
// the migration of version-1 sessions, and durability of committed chunks under kill -9.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <random>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include "accelcal/base/error.h"
#include "accelcal/session/session_store.h"
#include "accelcal/session/session_journal.h"

#include "session_test_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

namespace fs = std::filesystem;

constexpr int kChunkSamples = 500;

// Chunk `index` of a 100 Hz record: t = 5 index + k / 100 (the chunks follow each other);
// awkward values (fractions, NaN temperatures) so that bit-exactness is tested.
RecordChunk MakeChunk(long index, double t_shift_s = 0.0) {
  std::mt19937 rng(static_cast<unsigned>(index) + 17);
  std::normal_distribution<double> noise(0.0, 1.3);
  RecordChunk c;
  c.index = index;
  c.wall_end_s = 1.7e9 + static_cast<double>(index);
  for (int k = 0; k < kChunkSamples; ++k) {
    Sample s;
    s.t_s = t_shift_s + 5.0 * static_cast<double>(index) + k / 100.0;
    s.raw_counts = Eigen::Vector3d(2048 + noise(rng), 2047.5 + noise(rng), 2400 + noise(rng));
    s.temp_c = k % 3 == 0 ? kNaN : 25.0 + 0.001 * k;
    c.samples.push_back(s);
  }
  return c;
}

using accelcal::testing::SameBits;

void ExpectSameSamples(const std::vector<Sample>& a, const std::vector<Sample>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_TRUE(SameBits(a[i].t_s, b[i].t_s)) << i;
    for (int j = 0; j < 3; ++j) ASSERT_TRUE(SameBits(a[i].raw_counts(j), b[i].raw_counts(j))) << i;
    ASSERT_TRUE(SameBits(a[i].temp_c, b[i].temp_c)) << i;
  }
}

using SessionRecordTest = testing::SessionDirTest;

// Chunks 0 and 1, a gap of 7.25 s, chunk 2: what a record interrupted once holds.
void WriteInterruptedRecord(SessionJournal& journal, std::vector<Sample>* expected) {
  for (long i = 0; i < 2; ++i) {
    const RecordChunk c = MakeChunk(i);
    journal.AppendRecordChunk("drift", c);
    expected->insert(expected->end(), c.samples.begin(), c.samples.end());
  }
  RecordChunk third = MakeChunk(2, 7.25);
  third.gap_before = RecordGap{MakeChunk(1).samples.back().t_s, third.samples.front().t_s,
                               "resumed after interruption"};
  journal.AppendRecordChunk("drift", third);
  expected->insert(expected->end(), third.samples.begin(), third.samples.end());
}

void ExpectInterruptedRecord(const SessionJournal& journal, const std::vector<Sample>& expected) {
  const JournalRecord r = ReadRecord(journal, "drift");
  ExpectSameSamples(r.samples, expected);
  ASSERT_EQ(r.gaps.size(), 1u);
  EXPECT_EQ(r.gaps[0].t_start_s, expected[2 * kChunkSamples - 1].t_s);
  EXPECT_EQ(r.gaps[0].t_end_s, expected[2 * kChunkSamples].t_s);
  EXPECT_EQ(r.gaps[0].reason, "resumed after interruption");
  const RecordSummary s = journal.RecordSummaryOf("drift");
  EXPECT_EQ(s.num_chunks, 3);
  EXPECT_EQ(s.num_samples, 3 * kChunkSamples);
  EXPECT_EQ(s.t_first_s, 0.0);
  EXPECT_EQ(s.t_last_s, expected.back().t_s);
  EXPECT_EQ(s.last_wall_end_s, 1.7e9 + 2.0);
  EXPECT_EQ(s.num_gaps, 1);
  // The gap: from the last sample of chunk 1 (9.99 s) to the first of chunk 2 (17.25 s).
  EXPECT_NEAR(s.gaps_s, 17.25 - 9.99, 1e-9);
  EXPECT_NEAR(s.recorded_s(), s.span_s() - (17.25 - 9.99), 1e-9);
  EXPECT_EQ(journal.RecordSteps(), std::vector<std::string>{"drift"});
  EXPECT_EQ(journal.RecordSummaryOf("noise").num_chunks, 0);
}

TEST_F(SessionRecordTest, ChunksAndGapsRoundTripThroughAReopen) {
  std::vector<Sample> expected;
  {
    auto store = SessionStore::Open(path_, {});
    WriteInterruptedRecord(*store, &expected);
  }
  auto reader = SessionStore::Open(path_, Reader());
  ExpectInterruptedRecord(*reader, expected);
  EXPECT_TRUE(reader->Captures().empty());  // a record is not a capture
}

TEST(MemoryJournalRecordTest, KeepsTheSameContract) {
  auto journal = MakeMemoryJournal();
  std::vector<Sample> expected;
  WriteInterruptedRecord(*journal, &expected);
  ExpectInterruptedRecord(*journal, expected);
}

void ExpectRefusals(SessionJournal& journal) {
  journal.AppendRecordChunk("drift", MakeChunk(0));
  EXPECT_THROW(journal.AppendRecordChunk("drift", MakeChunk(0)), Error);  // again
  EXPECT_THROW(journal.AppendRecordChunk("drift", MakeChunk(2)), Error);  // a hole
  RecordChunk back = MakeChunk(1, -1.0);  // starts before the last sample stored
  EXPECT_THROW(journal.AppendRecordChunk("drift", back), Error);
  RecordChunk empty = MakeChunk(1);
  empty.samples.clear();
  EXPECT_THROW(journal.AppendRecordChunk("drift", empty), Error);
  RecordChunk bad_gap = MakeChunk(1, 3.0);
  bad_gap.gap_before = RecordGap{0.0, 8.0, "wrong start"};
  EXPECT_THROW(journal.AppendRecordChunk("drift", bad_gap), Error);
  EXPECT_EQ(journal.RecordSummaryOf("drift").num_chunks, 1);
  EXPECT_EQ(journal.RecordSummaryOf("drift").num_gaps, 0);
}

TEST_F(SessionRecordTest, RefusesChunksOutOfOrderAndChangesNothing) {
  auto store = SessionStore::Open(path_, {});
  ExpectRefusals(*store);
  ExpectRefusals(*MakeMemoryJournal());
}

// A session written before records existed (schema version 1: no record tables, and the
// capture statistics' co-moment columns still named cov_*, as versions 1 and 2 named them).
void MakeVersionOneSession(const std::string& path) {
  {
    auto store = SessionStore::Open(path, {});
    store->RecordInput("welcome", "device", "SN7");
  }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  std::string sql = "DROP TABLE record_chunks; DROP TABLE record_gaps; PRAGMA user_version = 1;";
  for (const char* c : {"xx", "xy", "xz", "yy", "yz", "zz"})
    sql += std::string(" ALTER TABLE captures RENAME COLUMN comoment_") + c + "_counts2 TO cov_" + c + "_counts2;";
  ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
}

std::int64_t UserVersion(const std::string& path) {
  sqlite3* db = nullptr;
  sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr);
  sqlite3_stmt* st = nullptr;
  sqlite3_prepare_v2(db, "PRAGMA user_version", -1, &st, nullptr);
  sqlite3_step(st);
  const std::int64_t v = sqlite3_column_int64(st, 0);
  sqlite3_finalize(st);
  sqlite3_close(db);
  return v;
}

TEST_F(SessionRecordTest, AVersionOneSessionIsReadAsItIsAndMigratedByAWriter) {
  MakeVersionOneSession(path_);
  {
    auto reader = SessionStore::Open(path_, Reader());
    EXPECT_EQ(reader->Inputs().at("welcome").at("device"), "SN7");
    EXPECT_EQ(reader->RecordSummaryOf("drift").num_chunks, 0);
    EXPECT_TRUE(reader->RecordSteps().empty());
  }
  EXPECT_EQ(UserVersion(path_), 1);
  {
    auto writer = SessionStore::Open(path_, {});
    EXPECT_EQ(writer->Inputs().at("welcome").at("device"), "SN7");
    writer->AppendRecordChunk("drift", MakeChunk(0));
  }
  EXPECT_EQ(UserVersion(path_), 7);  // the current version (4 checksums, 5 redo, 6 lab identity, 7 sensors)
  EXPECT_EQ(SessionStore::Open(path_, Reader())->RecordSummaryOf("drift").num_chunks, 1);
}

// The child appends chunks from `first` on, reporting each index on `fd` only after
// AppendRecordChunk returned (so whatever the parent read must be in the store).
[[noreturn]] void AppendForever(const std::string& path, long first, int fd) {
  auto store = SessionStore::Open(path, {});
  for (long i = first;; ++i) {
    store->AppendRecordChunk("drift", MakeChunk(i));
    const std::string line = std::to_string(i) + "\n";
    if (write(fd, line.data(), line.size()) < 0) _exit(1);
  }
}

TEST_F(SessionRecordTest, KillNineWhileAppendingLosesNoCommittedChunk) {
  std::mt19937 rng(20261122);
  std::uniform_int_distribution<int> delay_us(20000, 200000);
  std::set<long> reported;
  long stored_before = 0;
  // Every stored chunk is whole and unchanged, in order from 0; every reported one is there;
  // the count never goes down. Returns the next index.
  auto check = [&]() {
    auto store = SessionStore::Open(path_, {});
    long next = 0;
    store->VisitRecordChunks("drift", [&](const RecordChunk& c) {
      EXPECT_EQ(c.index, next);
      ExpectSameSamples(c.samples, MakeChunk(c.index).samples);
      ++next;
    });
    EXPECT_GE(next, stored_before) << "a committed chunk disappeared";
    for (long i : reported) EXPECT_LT(i, next) << "lost chunk " << i;
    stored_before = next;
    return next;
  };
  for (int round = 0; round < 12; ++round) {
    const long next = check();
    if (::testing::Test::HasFailure()) return;
    // Every other round after the child's first commit: progress however loaded the machine.
    const std::set<long> got = testing::RunAndKill(
        [&](int fd) { AppendForever(path_, next, fd); }, delay_us(rng), round % 2 == 0);
    reported.insert(got.begin(), got.end());
  }
  check();
  EXPECT_GT(reported.size(), 5u) << "the children hardly appended anything; the test proves little";
}

}  // namespace
}  // namespace accelcal
