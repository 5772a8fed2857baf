// Issue 17, item 5: silent corruption of a session file. Each capture and record chunk carries a
// checksum (schema version 4); a row damaged after it was written is left out and named, never
// read as data. The damage is made by flipping bytes of the file itself (as a bad disk or copy
// would), or by changing one stored value behind the store's back.
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include "accelcal/app/analyze_recording.h"
#include "accelcal/base/error.h"
#include "accelcal/session/session_store.h"
#include "session_test_support.h"

namespace accelcal {
namespace {

namespace fs = std::filesystem;
using SessionIntegrityTest = testing::SessionDirTest;

Capture NoisyCapture(int id, int n) {
  std::mt19937 rng(static_cast<unsigned>(id));
  std::normal_distribution<double> noise(0.0, 1.5);
  Capture c;
  c.id = id;
  c.kind = CaptureKind::kStatic;
  c.label = "pose " + std::to_string(id);
  for (int k = 0; k < n; ++k) {
    Sample s;
    s.t_s = 100.0 * id + k / 100.0;
    s.raw_counts = Eigen::Vector3d(2048 + noise(rng), 2047 + noise(rng), 2400 + noise(rng));
    s.temp_c = 25.0;
    c.samples.push_back(s);
  }
  return c;
}

RecordChunk NoisyChunk(long index, int n) {
  RecordChunk c;
  c.index = index;
  c.wall_end_s = 1.7e9 + static_cast<double>(index);
  std::mt19937 rng(static_cast<unsigned>(index) + 99);
  std::normal_distribution<double> noise(0.0, 1.5);
  for (int k = 0; k < n; ++k) {
    Sample s;
    s.t_s = static_cast<double>(index * n + k) / 100.0;
    s.raw_counts = Eigen::Vector3d(2048 + noise(rng), 2047 + noise(rng), 2400 + noise(rng));
    c.samples.push_back(s);
  }
  return c;
}

bool SameSamples(const std::vector<Sample>& a, const std::vector<Sample>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].t_s != b[i].t_s || a[i].raw_counts != b[i].raw_counts) return false;
  return true;
}

// Flips (XOR 0x5A) `count` bytes of the file from `offset`.
void FlipBytes(const std::string& path, std::uintmax_t offset, int count) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  ASSERT_TRUE(f.good());
  std::vector<char> bytes(static_cast<size_t>(count));
  f.seekg(static_cast<std::streamoff>(offset));
  f.read(bytes.data(), count);
  for (char& b : bytes) b = static_cast<char>(b ^ 0x5A);
  f.seekp(static_cast<std::streamoff>(offset));
  f.write(bytes.data(), count);
}

// The middle of the file, 1 kB into its page (clear of the page's own header, so that the
// damage lands in stored data rather than in SQLite's structure, which SQLite itself reports).
std::uintmax_t MiddleOfFile(const std::string& path) {
  const std::uintmax_t size = fs::file_size(path);
  return size / 2 / 4096 * 4096 + 1024;
}

void Exec(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
  sqlite3_close(db);
}

// A record of `chunks` chunks of `n` samples at step "drift", then `damage` (SQL) run on the file
// behind the store's back, as a bad disk or copy would.
void WriteDamagedRecord(const std::string& path, const SessionOpenOptions& writer, long chunks, int n,
                        const std::string& damage) {
  {
    auto store = SessionStore::Open(path, writer);
    for (long i = 0; i < chunks; ++i) store->AppendRecordChunk("drift", NoisyChunk(i, n));
  }
  Exec(path, damage);
}

std::vector<Capture> WriteTwelveCaptures(const std::string& path) {
  std::vector<Capture> stored;
  SessionOpenOptions writer;
  writer.procedure = "bench_default";
  writer.source = "sim";
  auto store = SessionStore::Open(path, writer);
  for (int id = 1; id <= 12; ++id) {
    stored.push_back(NoisyCapture(id, 1500));
    store->RecordCapture("face_" + std::to_string(id), stored.back());
  }
  return stored;
}

// The adversarial test's case: 64 bytes flipped in the middle of a session file. Before the
// checksums, every capture came back, one of them with different samples (its noise 50 times
// what was recorded).
TEST_F(SessionIntegrityTest, SixtyFourBytesFlippedInTheMiddleNeverComeBackAsData) {
  const std::vector<Capture> stored = WriteTwelveCaptures(path_);
  FlipBytes(path_, MiddleOfFile(path_), 64);
  auto store = SessionStore::Open(path_, Reader());
  const std::vector<JournalCapture> read = store->Captures();
  for (const JournalCapture& c : read) {
    const int id = std::stoi(c.step_id.substr(5));
    EXPECT_TRUE(SameSamples(c.capture.samples, stored.at(static_cast<size_t>(id - 1)).samples))
        << c.step_id << " came back with samples it was not stored with";
  }
  const std::vector<DamagedCapture> damaged = store->DamagedCaptures();
  ASSERT_EQ(damaged.size(), 1u);
  EXPECT_EQ(read.size(), 11u);
  for (const JournalCapture& c : read) EXPECT_NE(c.step_id, damaged[0].step_id);
  EXPECT_NE(damaged[0].Describe().find("is damaged in the session file (its checksum does not "
                                       "match what it holds): left out"), std::string::npos)
      << damaged[0].Describe();
}

// The statistics columns are covered too (nothing reads them back today, but a tool might).
TEST_F(SessionIntegrityTest, AChangedStatisticOrLabelIsCaughtAndTheRestIsRead) {
  WriteTwelveCaptures(path_);
  Exec(path_, "UPDATE captures SET mean_x_counts = mean_x_counts + 1e-9 WHERE step_id = 'face_3';"
              "UPDATE captures SET label = 'pose 99' WHERE step_id = 'face_7'");
  auto store = SessionStore::Open(path_, Reader());
  EXPECT_EQ(store->Captures().size(), 10u);
  const std::vector<DamagedCapture> damaged = store->DamagedCaptures();
  ASSERT_EQ(damaged.size(), 2u);
  EXPECT_EQ(damaged[0].step_id, "face_3");
  EXPECT_EQ(damaged[1].step_id, "face_7");
}

// A damaged capture is taken again by a resumed wizard: the writer replaces the damaged row
// (and still refuses a second capture for an intact one).
TEST_F(SessionIntegrityTest, ADamagedCaptureCanBeTakenAgain) {
  const std::vector<Capture> stored = WriteTwelveCaptures(path_);
  Exec(path_, "UPDATE captures SET n = n + 1 WHERE step_id = 'face_2'");
  auto store = SessionStore::Open(path_, Writer());
  EXPECT_THROW(store->RecordCapture("face_1", stored[0]), Error);
  store->RecordCapture("face_2", stored[1]);
  EXPECT_EQ(store->Captures().size(), 12u);
  EXPECT_TRUE(store->DamagedCaptures().empty());
}

// A damaged record chunk is left out as a gap whose reason names it, never read as samples.
TEST_F(SessionIntegrityTest, ADamagedRecordChunkBecomesANamedGap) {
  constexpr int kN = 1000;
  WriteDamagedRecord(path_, Writer(), 8, kN, "UPDATE record_chunks SET samples = CAST(zeroblob(40000) AS BLOB) WHERE chunk_index = 3");
  auto store = SessionStore::Open(path_, Reader());
  const JournalRecord record = ReadRecord(*store, "drift");
  EXPECT_EQ(record.samples.size(), 7u * kN);
  ASSERT_EQ(record.gaps.size(), 1u);
  EXPECT_DOUBLE_EQ(record.gaps[0].t_start_s, NoisyChunk(2, kN).samples.back().t_s);
  EXPECT_DOUBLE_EQ(record.gaps[0].t_end_s, NoisyChunk(4, kN).samples.front().t_s);
  EXPECT_NE(record.gaps[0].reason.find("chunk 3 is damaged in the session file"), std::string::npos)
      << record.gaps[0].reason;
  for (const Sample& s : record.samples) EXPECT_NE(s.raw_counts.x(), 0.0);
}

// The LAST chunk damaged: there is no chunk after it to carry the gap, yet it is named like a
// middle one (it failed before: the record just ended before it, without a word): a gap at the
// record's end, from the last good sample to the damaged chunk's stated end, in ReadRecord and
// in the record's analysis (what `accelcal allan` writes and prints for a session).
TEST_F(SessionIntegrityTest, ADamagedLastRecordChunkIsNamedAsAGapToo) {
  constexpr int kN = 1000;
  WriteDamagedRecord(path_, Writer(), 8, kN, "UPDATE record_chunks SET samples = CAST(zeroblob(40000) AS BLOB) WHERE chunk_index = 7");
  auto store = SessionStore::Open(path_, Reader());
  const JournalRecord record = ReadRecord(*store, "drift");
  EXPECT_EQ(record.samples.size(), 7u * kN);
  ASSERT_EQ(record.gaps.size(), 1u);
  EXPECT_DOUBLE_EQ(record.gaps[0].t_start_s, NoisyChunk(6, kN).samples.back().t_s);
  EXPECT_DOUBLE_EQ(record.gaps[0].t_end_s, NoisyChunk(7, kN).samples.back().t_s);
  EXPECT_NE(record.gaps[0].reason.find("chunk 7 is damaged in the session file"), std::string::npos)
      << record.gaps[0].reason;
  for (const Sample& s : record.samples) EXPECT_NE(s.raw_counts.x(), 0.0);

  const RecordAnalysis a = AnalyzeJournalRecord(*store, "drift", RecordAnalysisOptions{});
  EXPECT_EQ(a.samples, 7 * kN);
  ASSERT_EQ(a.gaps.size(), 1u);
  EXPECT_DOUBLE_EQ(a.gaps[0].t_before_s, NoisyChunk(6, kN).samples.back().t_s);
  EXPECT_DOUBLE_EQ(a.gaps[0].t_after_s, NoisyChunk(7, kN).samples.back().t_s);
  EXPECT_EQ(a.gaps[0].missing_samples, kN);
  EXPECT_EQ(a.missing_samples, kN);
}

// Two damaged chunks at the end, and one in the middle: each hole is named, the end's reason
// naming both of its chunks.
TEST_F(SessionIntegrityTest, DamagedChunksInTheMiddleAndAtTheEndAreEachNamed) {
  constexpr int kN = 200;
  WriteDamagedRecord(path_, Writer(), 8, kN, "UPDATE record_chunks SET n = n + 1 WHERE chunk_index IN (2, 6, 7)");
  auto store = SessionStore::Open(path_, Reader());
  const JournalRecord record = ReadRecord(*store, "drift");
  EXPECT_EQ(record.samples.size(), 5u * kN);
  ASSERT_EQ(record.gaps.size(), 2u);
  EXPECT_NE(record.gaps[0].reason.find("chunk 2 is damaged"), std::string::npos) << record.gaps[0].reason;
  EXPECT_NE(record.gaps[1].reason.find("chunk 6 is damaged"), std::string::npos) << record.gaps[1].reason;
  EXPECT_NE(record.gaps[1].reason.find("chunk 7 is damaged"), std::string::npos) << record.gaps[1].reason;
  EXPECT_DOUBLE_EQ(record.gaps[1].t_start_s, NoisyChunk(5, kN).samples.back().t_s);
}

// Every chunk damaged: nothing of the record can be read. Reproduces a defect: the record was
// read as empty and its analysis said nothing of the damage.
TEST_F(SessionIntegrityTest, ARecordWithEveryChunkDamagedIsNamedNotReadAsEmpty) {
  constexpr int kN = 200;
  WriteDamagedRecord(path_, Writer(), 3, kN, "UPDATE record_chunks SET n = n + 1");
  auto store = SessionStore::Open(path_, Reader());
  try {
    ReadRecord(*store, "drift");
    ADD_FAILURE() << "a record whose every chunk is damaged was read";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("record 'drift'"), std::string::npos) << what;
    EXPECT_NE(what.find("none of its 3 stored chunks can be read"), std::string::npos) << what;
    EXPECT_NE(what.find("record it again"), std::string::npos) << what;
  }
  EXPECT_THROW(AnalyzeJournalRecord(*store, "drift", RecordAnalysisOptions{}), Error);
}

// Version 4 adds the checksums: a version-3 file (no checksum column) is read as it is by a
// reader, and a writer's migration computes the checksums of the rows it holds, values
// unchanged; damage after that is caught.
TEST_F(SessionIntegrityTest, AVersionThreeSessionGetsItsChecksumsFromAWriter) {
  const std::vector<Capture> stored = WriteTwelveCaptures(path_);
  {
    auto store = SessionStore::Open(path_, Writer());
    store->AppendRecordChunk("drift", NoisyChunk(0, 50));
  }
  Exec(path_, "ALTER TABLE captures DROP COLUMN checksum; ALTER TABLE record_chunks DROP COLUMN "
              "checksum; PRAGMA user_version = 3");
  EXPECT_EQ(SessionStore::Open(path_, Reader())->Captures().size(), 12u);
  SessionStore::Open(path_, Writer());  // migrates
  {
    auto store = SessionStore::Open(path_, Reader());
    const std::vector<JournalCapture> read = store->Captures();
    ASSERT_EQ(read.size(), 12u);
    for (size_t i = 0; i < read.size(); ++i) EXPECT_TRUE(SameSamples(read[i].capture.samples, stored[i].samples));
    EXPECT_TRUE(store->DamagedCaptures().empty());
    EXPECT_EQ(ReadRecord(*store, "drift").samples.size(), 50u);
  }
  Exec(path_, "UPDATE captures SET rpm = 120 WHERE step_id = 'face_5'; "
              "UPDATE record_chunks SET wall_end_s = 0 WHERE chunk_index = 0");
  auto store = SessionStore::Open(path_, Reader());
  ASSERT_EQ(store->DamagedCaptures().size(), 1u);
  EXPECT_EQ(store->DamagedCaptures()[0].step_id, "face_5");
  // Its only chunk damaged: named, not read as an empty record (it was read as empty before).
  EXPECT_THROW(ReadRecord(*store, "drift"), Error);
}

}  // namespace
}  // namespace accelcal
