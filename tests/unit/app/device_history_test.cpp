// A device's calibration history: the session listing by device, the moves between
// calibrations judged against the combined uncertainty, and the errors for unknown devices.
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include "accelcal/io/detail/json_forms.h"
#include "accelcal/session/detail/sqlite_db.h"
#include "accelcal/app/device_history.h"
#include "export_test_support.h"
#include "test_support.h"

namespace accelcal::device_history_test {
namespace {

namespace fs = std::filesystem;
using testing::Contains;

TEST(ParameterMove, JudgedAgainstTheCombinedSigma) {
  const ParameterMove m = MoveBetween(100.0, 0.3, 101.5, 0.4);  // sigma 0.5, 3 sigmas exactly
  EXPECT_DOUBLE_EQ(m.delta, 1.5);
  EXPECT_DOUBLE_EQ(m.sigma_combined, 0.5);
  EXPECT_DOUBLE_EQ(m.n_sigmas, 3.0);
  EXPECT_FALSE(m.changed);  // over 3, not at 3
  EXPECT_TRUE(MoveBetween(100.0, 0.3, 98.4, 0.4).changed);
  EXPECT_EQ(MoveBetween(1.0, 0.0, 1.0, 0.0).n_sigmas, 0.0);
  EXPECT_TRUE(std::isinf(MoveBetween(1.0, 0.0, 2.0, 0.0).n_sigmas));
}

class DeviceHistoryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("accelcal_history_{}", ::getpid());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A session of `device` created at `date`, with `cal` as its result when given.
  void Add(const std::string& name, const std::string& device, const std::string& date,
           const Calibration* cal) {
    const std::string path = (dir_ / (name + ".db")).string();
    {
      SessionOpenOptions o;
      o.procedure = "seed";
      auto store = SessionStore::Open(path, o);
      store->RecordInput(kSessionStep, kDeviceKey, device);
      if (cal != nullptr) store->RecordResult(CalibrationToJsonText(*cal));
    }
    detail::SqliteDb db(path, false);
    detail::SqliteStatement(db, "UPDATE session SET created_utc = ? WHERE id = 1").Bind(1, date).Run();
  }

  // A session of a fixture of `serials` created at `date`, sensor i calibrated as cals[i] (null:
  // not calibrated).
  void AddFixture(const std::string& name, const std::vector<std::string>& serials,
                  const std::string& date, const std::vector<const Calibration*>& cals) {
    const std::string path = (dir_ / (name + ".db")).string();
    {
      SessionOpenOptions o;
      o.procedure = "seed";
      auto store = SessionStore::Open(path, o);
      store->RecordInput(kSessionStep, kDeviceKey, "fixture");
      Fixture f;
      for (const std::string& serial : serials) {
        FixtureSensor sensor;
        sensor.serial = serial;
        f.sensors.push_back(sensor);
      }
      store->RecordSensors(f);
      for (std::size_t i = 0; i < cals.size(); ++i)
        if (cals[i] != nullptr) store->RecordSensorResult(static_cast<int>(i), CalibrationToJsonText(*cals[i]));
    }
    detail::SqliteDb db(path, false);
    detail::SqliteStatement(db, "UPDATE session SET created_utc = ? WHERE id = 1").Bind(1, date).Run();
  }

  fs::path dir_;
};

TEST_F(DeviceHistoryTest, InDateOrderWithTheMovesBetweenCalibrations) {
  Calibration a = testing::ExportTestCalibration();
  Calibration b = a, c = a;
  b.model.bias_counts.x() += 2.0;      // 2 / (0.05 sqrt 2) = 28 sigmas: changed
  c.model = b.model;
  c.model.a_zx_rad += 1e-4;            // 1e-4 / (1.2e-4 sqrt 2) = 0.6 sigma: not changed
  // Names out of date order, and another device in between.
  Add("z_first", "DEV-1", "2025-01-10T09:00:00.000Z", &a);
  Add("a_third", "DEV-1", "2025-09-10T09:00:00.000Z", &c);
  Add("m_second", "DEV-1", "2025-06-10T09:00:00.000Z", &b);
  Add("other", "DEV-2", "2025-05-01T09:00:00.000Z", &a);
  Add("unfinished", "DEV-1", "2025-07-01T09:00:00.000Z", nullptr);
  const DeviceHistory h = BuildDeviceHistory(dir_.string(), "DEV-1");
  ASSERT_EQ(h.entries.size(), 3u);
  EXPECT_EQ(h.entries[0].session.name, "z_first");
  EXPECT_EQ(h.entries[1].session.name, "m_second");
  EXPECT_EQ(h.entries[2].session.name, "a_third");
  EXPECT_EQ(h.sessions_without_result, 1);
  EXPECT_TRUE(h.entries[0].moves.empty());
  const ParameterMove& bias = h.entries[1].moves[kBiasX];
  EXPECT_NEAR(bias.delta, 2.0, 1e-12);
  EXPECT_NEAR(bias.n_sigmas, 2.0 / std::hypot(0.05, 0.05), 1e-9);
  EXPECT_TRUE(bias.changed);
  EXPECT_FALSE(h.entries[1].moves[kScaleX].changed);
  EXPECT_NEAR(h.entries[2].moves[kMisZX].delta, 1e-4, 1e-15);
  EXPECT_FALSE(h.entries[2].moves[kMisZX].changed);
  EXPECT_EQ(h.entries[2].moves[kBiasX].delta, 0.0);
  const nlohmann::json j = DeviceHistoryToJson(h);
  EXPECT_TRUE(j["calibrations"][0]["parameters"]["bias_x"]["delta"].is_null());
  EXPECT_EQ(j["calibrations"][1]["parameters"]["bias_x"]["changed"], true);
}

TEST_F(DeviceHistoryTest, UnknownDeviceListsTheKnownOnes) {
  const Calibration a = testing::ExportTestCalibration();
  Add("s1", "DEV-1", "2025-01-10T09:00:00.000Z", &a);
  Add("s2", "DEV-2", "2025-01-11T09:00:00.000Z", nullptr);
  try {
    BuildDeviceHistory(dir_.string(), "DEV-9");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "no session of device DEV-9")) << e.what();
    EXPECT_TRUE(Contains(e.what(), "devices there: DEV-1, DEV-2")) << e.what();
  }
  try {
    BuildDeviceHistory(dir_.string(), "DEV-2");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "device DEV-2 has 1 session(s)")) << e.what();
  }
  EXPECT_THROW(BuildDeviceHistory((dir_ / "nope").string(), "DEV-1"), Error);
}

TEST_F(DeviceHistoryTest, ListSessionsFiltersByDeviceAndProcedure) {
  Add("s1", "DEV-1", "2025-01-10T09:00:00.000Z", nullptr);
  Add("s2", "DEV-2", "2025-01-09T09:00:00.000Z", nullptr);
  std::ofstream(dir_ / "junk.db") << "not a database";
  const SessionListing all = ListSessions(dir_.string(), {});
  EXPECT_EQ(all.sessions.size(), 2u);
  ASSERT_EQ(all.unreadable.size(), 1u);
  EXPECT_TRUE(Contains(all.unreadable[0].path, "junk.db"));
  SessionFilter f;
  f.device = "DEV-2";
  const std::vector<SessionInfo> dev2 = ListSessions(dir_.string(), f).sessions;
  ASSERT_EQ(dev2.size(), 1u);
  EXPECT_EQ(dev2[0].name, "s2");
  f.procedure = "other";
  EXPECT_TRUE(ListSessions(dir_.string(), f).sessions.empty());
}

// Each sensor of a fixture's session is a device of its own: its calibration there joins the
// history of its serial, beside its sessions alone; a sensor not calibrated there is a session
// without a result.
TEST_F(DeviceHistoryTest, EachSensorOfAFixtureIsItsOwnDevice) {
  Calibration a = testing::ExportTestCalibration();
  Calibration b = a, other = a;
  b.model.bias_counts.y() += 3.0;
  other.model.bias_counts.z() += 50.0;
  Add("alone", "B2", "2025-01-10T09:00:00.000Z", &a);
  AddFixture("plate", {"B1", "B2", "B3"}, "2025-03-10T09:00:00.000Z", {&other, &b, nullptr});
  const DeviceHistory h = BuildDeviceHistory(dir_.string(), "B2");
  ASSERT_EQ(h.entries.size(), 2u);
  EXPECT_EQ(h.entries[0].session.name, "alone");
  EXPECT_EQ(h.entries[1].session.name, "plate");
  EXPECT_EQ(h.entries[1].session.device, "B2");
  EXPECT_EQ(h.entries[1].calibration.model.bias_counts, b.model.bias_counts);  // its own, not B1's
  EXPECT_NEAR(h.entries[1].moves[kBiasY].delta, 3.0, 1e-12);
  EXPECT_EQ(h.sessions_without_result, 0);
  // B3 has a session, not calibrated; the fixture's name is no device with a history.
  try {
    BuildDeviceHistory(dir_.string(), "B3");
    FAIL() << "B3 has no calibration";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("device B3 has 1 session(s)"), std::string::npos) << e.what();
  }
  try {
    BuildDeviceHistory(dir_.string(), "B9");
    FAIL() << "no B9";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("B1, B2, B3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace accelcal::device_history_test
