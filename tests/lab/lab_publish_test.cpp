// Publishing to the lab store: once per session whatever happens (twice, concurrently, after a
// lost connection), whole or not at all, numbers from the lab's sequence and never twice.
#include <atomic>
#include <map>
#include <set>
#include <thread>

#include "lab_test_support.h"

namespace accelcal {
namespace {

using detail::PgText;
using testing::BenchRoles;
using testing::kAdmin;
using testing::MakePublication;
using testing::NumberedRenderer;

class LabPublish : public testing::LabDatabaseTest {
 protected:
  bool StartMigrated() const override { return true; }
  void SetUp() override {
    LabDatabaseTest::SetUp();
  }

  static long long Count(const std::string& table) {
    return RawAs(kAdmin)->Exec("SELECT count(*) FROM accelcal." + table).Int(0, 0);
  }

  // Every session has its sensors, each sensor its calibration and certificate, each certificate
  // its two documents: nothing partial anywhere.
  static void ExpectWhole(long long sessions) {
    EXPECT_EQ(Count("sessions"), sessions);
    EXPECT_EQ(Count("session_sensors"), sessions);
    EXPECT_EQ(Count("calibrations"), sessions);
    EXPECT_EQ(Count("certificates"), sessions);
    EXPECT_EQ(Count("certificate_documents"), 2 * sessions);
    EXPECT_EQ(Count("session_equipment"), sessions);
    EXPECT_EQ(
        RawAs(kAdmin)->Exec("SELECT count(DISTINCT certificate_number) FROM accelcal.certificates").Int(0, 0),
        sessions);
  }
};

TEST_F(LabPublish, ASessionPublishedTwiceIsOneRowWithItsFirstNumber) {
  const LabPublication p = MakePublication(NewRandomUuid(), "DEV-1");
  const auto bench = As("bench_1");
  const LabPublishResult first = bench->Publish(p, NumberedRenderer());
  EXPECT_TRUE(first.newly_published);
  ASSERT_EQ(first.certificates.size(), 1u);
  EXPECT_EQ(first.certificates[0].certificate_number, "LAB-000001");
  int renders = 0;
  const LabPublishResult second =
      As("bench_1")->Publish(p, [&](const LabSensorCalibration& s, const std::string& n) {
        ++renders;
        return NumberedRenderer()(s, n);
      });
  EXPECT_FALSE(second.newly_published);
  EXPECT_EQ(renders, 0);
  ASSERT_EQ(second.certificates.size(), 1u);
  EXPECT_EQ(second.certificates[0].certificate_number, "LAB-000001");
  EXPECT_EQ(second.published_utc, first.published_utc);
  // The documents handed back are the ones stored when it was issued.
  ASSERT_EQ(second.certificates[0].documents.size(), 2u);
  EXPECT_EQ(second.certificates[0].documents[0].bytes, first.certificates[0].documents[0].bytes);
  ExpectWhole(1);
}

TEST_F(LabPublish, ACalibrationChangedAfterPublishingIsNotTakenAgain) {
  LabPublication p = MakePublication(NewRandomUuid(), "DEV-1");
  As("bench_1")->Publish(p, NumberedRenderer());
  p.sensors[0].calibration_json = "{\"calibration\": \"refitted\"}";
  try {
    As("bench_1")->Publish(p, NumberedRenderer());
    FAIL() << "a changed calibration was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("as certificate LAB-000001 with another calibration"),
              std::string::npos)
        << e.what();
  }
  ExpectWhole(1);
}

TEST_F(LabPublish, ASessionOfTwoSensorsHasACalibrationAndANumberEach) {
  LabPublication p = MakePublication(NewRandomUuid(), "BOARD-A");
  LabSensorCalibration second = p.sensors[0];
  second.sensor_index = 1;
  second.device_serial = "BOARD-B";
  second.verdict = "FAIL";
  p.sensors.push_back(second);
  const LabPublishResult r = As("bench_1")->Publish(p, NumberedRenderer());
  ASSERT_EQ(r.certificates.size(), 2u);
  EXPECT_NE(r.certificates[0].certificate_number, r.certificates[1].certificate_number);
  EXPECT_EQ(As("bench_2")->History("BOARD-B").entries.at(0).verdict, "FAIL");
  EXPECT_EQ(As("bench_2")->History("BOARD-A").entries.at(0).certificate_number,
            r.certificates[0].certificate_number);
  EXPECT_EQ(Count("sessions"), 1);
  EXPECT_EQ(Count("session_sensors"), 2);
  EXPECT_EQ(Count("certificates"), 2);
}

TEST_F(LabPublish, AFailureHalfWayLeavesNothing) {
  const LabPublication p = MakePublication(NewRandomUuid(), "DEV-1");
  EXPECT_THROW(
      As("bench_1")->Publish(p,
                             [](const LabSensorCalibration&, const std::string&) -> std::vector<LabDocument> {
                               throw Error("the renderer failed");
                             }),
      Error);
  ExpectWhole(0);
  EXPECT_EQ(Count("devices"), 0);
  // Published later, whole; the number drawn by the failed attempt is not used again.
  const LabPublishResult r = As("bench_1")->Publish(p, NumberedRenderer());
  EXPECT_EQ(r.certificates.at(0).certificate_number, "LAB-000002");
  ExpectWhole(1);
}

// The connection dies in the middle of a publish (the server ends the backend while the
// certificate is being rendered): nothing of it stays, and the retry publishes it once.
TEST_F(LabPublish, ALostConnectionLeavesNothingAndTheRetryPublishesOnce) {
  const LabPublication p = MakePublication(NewRandomUuid(), "DEV-1");
  const auto bench = As("bench_1");
  auto superuser = RawAs("postgres");  // (ending another role's backend takes a superuser)
  try {
    bench->Publish(p, [&](const LabSensorCalibration& s, const std::string& n) {
      superuser->Exec(
          "SELECT pg_terminate_backend(pid) FROM pg_stat_activity WHERE usename = 'bench_1' AND datname = $1",
          {PgText(database())});
      return NumberedRenderer()(s, n);
    });
    FAIL() << "the publish went through a dead connection";
  } catch (const LabError& e) {
    EXPECT_TRUE(e.unreachable()) << e.sqlstate() << " " << e.what();
  }
  ExpectWhole(0);
  EXPECT_TRUE(As("bench_1")->Publish(p, NumberedRenderer()).newly_published);
  EXPECT_FALSE(As("bench_1")->Publish(p, NumberedRenderer()).newly_published);
  ExpectWhole(1);
}

// Eight benches publish 100 sessions each at once: 800 sessions, 800 distinct numbers, nothing
// lost, nothing twice.
TEST_F(LabPublish, EightConcurrentPublishersOfAHundredSessionsEach) {
  constexpr int kPublishers = 8, kSessions = 100;
  std::vector<std::vector<std::string>> numbers(kPublishers);
  std::vector<std::string> errors(kPublishers);
  std::vector<std::unique_ptr<LabStore>> stores;
  for (int t = 0; t < kPublishers; ++t) stores.push_back(As(BenchRoles()[static_cast<size_t>(t)]));
  std::vector<std::thread> threads;
  for (int t = 0; t < kPublishers; ++t)
    threads.emplace_back([&, t] {
      try {
        for (int i = 0; i < kSessions; ++i) {
          const LabPublishResult r = stores[static_cast<size_t>(t)]->Publish(
              MakePublication(NewRandomUuid(), fmt::format("DEV-{}", i % 10)), NumberedRenderer());
          if (!r.newly_published) throw Error("a new session was found already published");
          numbers[static_cast<size_t>(t)].push_back(r.certificates.at(0).certificate_number);
        }
      } catch (const std::exception& e) {
        errors[static_cast<size_t>(t)] = e.what();
      }
    });
  for (std::thread& t : threads) t.join();
  std::set<std::string> all;
  for (int t = 0; t < kPublishers; ++t) {
    EXPECT_EQ(errors[static_cast<size_t>(t)], "") << "publisher " << t;
    EXPECT_EQ(numbers[static_cast<size_t>(t)].size(), static_cast<size_t>(kSessions));
    all.insert(numbers[static_cast<size_t>(t)].begin(), numbers[static_cast<size_t>(t)].end());
  }
  EXPECT_EQ(all.size(), static_cast<size_t>(kPublishers * kSessions));
  ExpectWhole(kPublishers * kSessions);
  // Each bench's sessions are its own, by the database's account.
  for (int t = 0; t < kPublishers; ++t)
    EXPECT_EQ(RawAs(kAdmin)
                  ->Exec("SELECT count(*) FROM accelcal.sessions WHERE bench = $1",
                         {PgText(BenchRoles()[static_cast<size_t>(t)])})
                  .Int(0, 0),
              kSessions);
}

// Eight publishers race over the same 40 sessions (a copied session file, a retry beside the
// first attempt): one row each, and every publisher is handed the same number for it.
TEST_F(LabPublish, PublishersRacingOverTheSameSessionsMakeOneRowEach) {
  constexpr int kPublishers = 8, kSessions = 40;
  std::vector<LabPublication> shared;
  for (int i = 0; i < kSessions; ++i)
    shared.push_back(MakePublication(NewRandomUuid(), fmt::format("DEV-{}", i)));
  std::vector<std::map<std::string, std::string>> seen(kPublishers);
  std::vector<int> new_ones(kPublishers, 0);
  std::vector<std::string> errors(kPublishers);
  std::vector<std::unique_ptr<LabStore>> stores;
  for (int t = 0; t < kPublishers; ++t) stores.push_back(As("bench_1"));  // one bench, eight processes
  std::vector<std::thread> threads;
  for (int t = 0; t < kPublishers; ++t)
    threads.emplace_back([&, t] {
      try {
        for (int i = 0; i < kSessions; ++i) {
          const LabPublication& p = shared[static_cast<size_t>((i + t * 5) % kSessions)];
          const LabPublishResult r = stores[static_cast<size_t>(t)]->Publish(p, NumberedRenderer());
          new_ones[static_cast<size_t>(t)] += r.newly_published;
          seen[static_cast<size_t>(t)][p.session_uuid] = r.certificates.at(0).certificate_number;
        }
      } catch (const std::exception& e) {
        errors[static_cast<size_t>(t)] = e.what();
      }
    });
  for (std::thread& t : threads) t.join();
  int total_new = 0;
  for (int t = 0; t < kPublishers; ++t) {
    EXPECT_EQ(errors[static_cast<size_t>(t)], "") << "publisher " << t;
    EXPECT_EQ(seen[static_cast<size_t>(t)], seen[0]) << "publisher " << t << " was handed other numbers";
    total_new += new_ones[static_cast<size_t>(t)];
  }
  EXPECT_EQ(total_new, kSessions);
  ExpectWhole(kSessions);
}

TEST_F(LabPublish, AnIncompleteRequestIsRefusedBeforeTheStore) {
  LabPublication p = MakePublication("not-a-uuid", "DEV-1");
  EXPECT_THROW(As("bench_1")->Publish(p, NumberedRenderer()), Error);
  p = MakePublication(NewRandomUuid(), "");
  EXPECT_THROW(As("bench_1")->Publish(p, NumberedRenderer()), Error);
  ExpectWhole(0);
}

}  // namespace
}  // namespace accelcal
