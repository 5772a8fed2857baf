// The noise analysis on simulated records whose truth is known: white noise (std within 5 %,
// density within 10 %), non-normal records flagged, quantized ones not tested, three days with
// known offsets giving the repeatability figure; and the records found in a session store.
#include "accelcal/analysis/noise_analysis.h"

#include <cmath>
#include <filesystem>
#include <random>

#include <fmt/core.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include "accelcal/app/noise_records.h"
#include "accelcal/base/error.h"
#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/report/noise_text.h"
#include "accelcal/session/detail/sqlite_db.h"
#include "accelcal/session/session_catalog.h"
#include "accelcal/session/session_store.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/virtual_bench.h"
#include "accelcal/session/procedure.h"
#include "test_support.h"

namespace accelcal::analysis {
namespace {

// A 60 s static record at 100 Hz, z up, level, white noise `sigma_counts`, the default bench's
// sensor with `bias_offset` added to its bias.
NoiseRecord SimulatedRecord(double sigma_counts, std::uint64_t seed,
                            const Eigen::Vector3d& bias_offset = Eigen::Vector3d::Zero(),
                            std::string date = "") {
  sim::Scenario s = sim::DefaultScenario();
  s.sensor.noise_counts = Eigen::Vector3d::Constant(sigma_counts);
  s.sensor.model.bias_counts += bias_offset;
  s.bench.seed = seed;
  s.bench.placement_error_deg = 0.0;
  s.captures.resize(1);
  s.captures[0] = sim::CapturePlan{};
  s.captures[0].label = "z up";
  s.captures[0].duration_s = 60.0;
  return {fmt::format("sim seed {}", seed), std::move(date),
          sim::VirtualBench(s).SimulateCaptureSet()[0].samples};
}

TEST(NoiseAnalysisTest, WhiteNoiseStdAndDensity) {
  const double sigma = 3.0;
  const NoiseReport report = AnalyzeNoise({SimulatedRecord(sigma, 21)});
  ASSERT_EQ(report.records.size(), 1u);
  const RecordNoise& r = report.records[0];
  EXPECT_EQ(report.unit, "counts");
  EXPECT_EQ(r.num_samples, 6000);
  EXPECT_NEAR(r.rate_hz, 100.0, 1e-6);
  EXPECT_NEAR(r.band_low_hz, 5.0, 1e-9);   // 0.1 Nyquist
  EXPECT_NEAR(r.band_high_hz, 40.0, 1e-9);  // 0.8 Nyquist
  // Rounding to whole counts adds 1/12 count^2 of white noise.
  const double true_std = std::sqrt(sigma * sigma + 1.0 / 12.0);
  const double true_density = true_std / std::sqrt(100.0);  // N = s/sqrt(fs), counts/sqrt(Hz)
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(r.axes[a].std / true_std, 1.0, 0.05) << a;
    EXPECT_NEAR(r.axes[a].density / true_density, 1.0, 0.10) << a;
    EXPECT_EQ(r.axes[a].normality.verdict, NormalityVerdict::kNormal) << r.axes[a].normality.note;
  }
  // The mean is the true reading of +z up: raw = K T^-1 [0, 0, g] + b (sensor_model.h); the
  // noise moves it by sigma / sqrt(6000) = 0.04 counts.
  const sim::Scenario truth = sim::DefaultScenario();
  const SensorModel& m = truth.sensor.model;
  const Eigen::Vector3d raw =
      m.scale_counts_per_mps2.cwiseProduct(m.Misalignment().inverse() *
                                           Eigen::Vector3d(0, 0, truth.bench.gravity_mps2)) +
      m.bias_counts;
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(r.axes[a].mean, raw(a), 0.2) << a;
  EXPECT_LE(r.spectrum.frequency_hz.size(), 200u);
  EXPECT_GT(r.spectrum.frequency_hz.size(), 100u);
  for (std::size_t i = 1; i < r.spectrum.frequency_hz.size(); ++i)
    ASSERT_GT(r.spectrum.frequency_hz[i], r.spectrum.frequency_hz[i - 1]);
  // One day: no repeatability figure, and the result says why.
  EXPECT_TRUE(std::isnan(report.repeatability.std_of_means(0)));
  ASSERT_FALSE(report.warnings.empty());
  EXPECT_TRUE(testing::Contains(report.warnings.back(), "needs records on 3 different days; have 1"))
      << report.warnings.back();
}

TEST(NoiseAnalysisTest, NonNormalRecordsAreFlagged) {
  // Uniform noise (excess kurtosis -1.2), unrounded.
  NoiseRecord uniform = SimulatedRecord(0.0, 1);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  for (Sample& s : uniform.samples) s.raw_counts += Eigen::Vector3d(u(rng), u(rng), u(rng));
  // A step of 10 counts half way on a record of 1.5 counts white noise: bimodal.
  NoiseRecord step = SimulatedRecord(1.5, 2);
  for (std::size_t i = step.samples.size() / 2; i < step.samples.size(); ++i)
    step.samples[i].raw_counts.x() += 10.0;
  const NoiseReport report = AnalyzeNoise({uniform, step});
  for (int a = 0; a < 3; ++a)
    EXPECT_EQ(report.records[0].axes[a].normality.verdict, NormalityVerdict::kNotNormal) << a;
  EXPECT_EQ(report.records[1].axes[0].normality.verdict, NormalityVerdict::kNotNormal);
  EXPECT_EQ(report.records[1].axes[1].normality.verdict, NormalityVerdict::kNormal);
  EXPECT_NEAR(report.records[0].axes[0].normality.excess_kurtosis, -1.2, 0.1);
}

TEST(NoiseAnalysisTest, SubCountNoiseIsNotTestedForNormality) {
  const NoiseReport report = AnalyzeNoise({SimulatedRecord(0.3, 5)});
  for (int a = 0; a < 3; ++a) {
    const NormalityTest& t = report.records[0].axes[a].normality;
    EXPECT_EQ(t.verdict, NormalityVerdict::kQuantized) << t.note;
    EXPECT_TRUE(testing::Contains(t.note, "rounding")) << t.note;
  }
}

TEST(NoiseAnalysisTest, ThreeDaysWithKnownOffsetsGiveTheRepeatability) {
  // Turn-on biases x: +0, +2, +4 counts (std 2, range 4); y: 0, 0, -3 (std sqrt(3), range 3).
  // The noise adds sigma / sqrt(n) = 1.5 / sqrt(6000) = 0.02 counts to each mean.
  const std::vector<NoiseRecord> records = {
      SimulatedRecord(1.5, 11, {0, 0, 0}, "2026-03-01"),
      SimulatedRecord(1.5, 12, {2, 0, 0}, "2026-03-02"),
      SimulatedRecord(1.5, 13, {2, 5, 0}, "2026-03-02"),  // same day: left out
      SimulatedRecord(1.5, 14, {4, -3, 0}, "2026-03-04")};
  const NoiseReport report = AnalyzeNoise(records);
  const BiasRepeatability& rep = report.repeatability;
  EXPECT_EQ(rep.num_days, 3);
  EXPECT_EQ(rep.dates, (std::vector<std::string>{"2026-03-01", "2026-03-02", "2026-03-04"}));
  EXPECT_NEAR(rep.std_of_means(0), 2.0, 0.1);
  EXPECT_NEAR(rep.max_minus_min(0), 4.0, 0.1);
  EXPECT_NEAR(rep.std_of_means(1), std::sqrt(3.0), 0.1);
  EXPECT_NEAR(rep.max_minus_min(1), 3.0, 0.1);
  EXPECT_LT(rep.max_minus_min(2), 0.1);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_TRUE(testing::Contains(report.warnings[0], "a day already counted")) << report.warnings[0];
  // The JSON carries the same figures.
  const nlohmann::json j = NoiseReportToJson(report);
  EXPECT_EQ(j["repeatability"]["days"], 3);
  EXPECT_DOUBLE_EQ(j["repeatability"]["std_of_means"][0].get<double>(), rep.std_of_means(0));
  EXPECT_EQ(j["records"][0]["axes"]["x"]["normality"]["verdict"], "normal");
  EXPECT_TRUE(j["records"][0]["spectrum"]["z"].is_array());
  for (const std::string& line : [&] {
         std::vector<std::string> lines;
         std::string text = FormatNoiseText(report), cur;
         for (char c : text) {
           if (c == '\n') { lines.push_back(cur); cur.clear(); } else { cur += c; }
         }
         return lines;
       }()) {
    EXPECT_LE(line.size(), 80u) << line;
  }
}

TEST(NoiseAnalysisTest, CalibrationGivesMetresPerSecondSquared) {
  const sim::Scenario truth = sim::DefaultScenario();
  Calibration cal;
  cal.model = truth.sensor.model;
  cal.source = "truth.json";
  const NoiseReport report = AnalyzeNoise({SimulatedRecord(3.0, 8)}, {}, &cal);
  EXPECT_EQ(report.unit, "m/s^2");
  EXPECT_EQ(report.calibration_source, "truth.json");
  const RecordNoise& r = report.records[0];
  EXPECT_NEAR(r.axes[2].mean, truth.bench.gravity_mps2, 0.01);
  const double true_std_z = std::sqrt(9.0 + 1.0 / 12.0) / truth.sensor.model.scale_counts_per_mps2(2);
  EXPECT_NEAR(r.axes[2].std / true_std_z, 1.0, 0.05);
  EXPECT_NEAR(r.axes[2].std_counts, std::sqrt(9.0 + 1.0 / 12.0), 0.15);
}

TEST(NoiseAnalysisTest, RefusesBadInput) {
  EXPECT_THROW(AnalyzeNoise({}), Error);
  NoiseRecord short_record = SimulatedRecord(1.5, 3);
  short_record.samples.resize(10);
  EXPECT_THROW(AnalyzeNoise({short_record}), Error);
  NoiseRecord backwards = SimulatedRecord(1.5, 3);
  backwards.samples[100].t_s = backwards.samples[99].t_s;
  EXPECT_THROW(AnalyzeNoise({backwards}), Error);
  NoiseAnalysisOptions bad;
  bad.band_high_fraction = 0.05;
  EXPECT_THROW(AnalyzeNoise({SimulatedRecord(1.5, 3)}, bad), Error);
}

// --- Records from the session store. ---

class NoiseSessionsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("accelcal_noise_sessions_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    procedure_ = LoadProcedure(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/noise.toml");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // A session of `procedure` for `device`, created at `created_utc`, holding `record` at
  // step `step` (none when empty).
  void MakeSession(const std::string& name, const std::string& procedure,
                   const std::string& device, const std::string& created_utc,
                   const std::string& step, const NoiseRecord& record) {
    const std::string path = (dir_ / (name + ".db")).string();
    {
      SessionOpenOptions options;
      options.procedure = procedure;
      options.source = "sim";
      auto store = SessionStore::Open(path, options);
      store->RecordInput(kSessionStep, kDeviceKey, device);
      if (!step.empty()) {
        Capture c;
        c.id = 1;
        c.label = "+z up";
        c.samples = record.samples;
        store->RecordCapture(step, c);
      }
    }
    detail::SqliteDb db(path, false);
    detail::SqliteStatement(db, "UPDATE session SET created_utc = ? WHERE id = 1")
        .Bind(1, created_utc).Run();
  }

  std::filesystem::path dir_;
  Procedure procedure_;
};

TEST_F(NoiseSessionsTest, FindsTheDevicesRecordsSortedByCreation) {
  const std::string title = procedure_.title;
  const NoiseRecord r = SimulatedRecord(1.5, 1);
  MakeSession("c", title, "SN-1", "2026-03-03T09:00:00.000Z", "noise", r);
  MakeSession("a", title, "SN-1", "2026-03-01T09:00:00.000Z", "noise", r);
  MakeSession("b", title, "SN-1", "2026-03-02T09:00:00.000Z", "", r);  // no record yet
  MakeSession("d", title, "SN-2", "2026-03-01T10:00:00.000Z", "noise", r);
  MakeSession("e", "Full calibration", "SN-1", "2026-03-01T11:00:00.000Z", "pose_pz", r);

  const SessionListing all = ListSessions(dir_.string());
  ASSERT_EQ(all.sessions.size(), 5u);
  EXPECT_EQ(all.sessions.front().name, "a");
  const SessionListing sn1 = ListSessions(dir_.string(), {"SN-1", title});
  ASSERT_EQ(sn1.sessions.size(), 3u);
  EXPECT_EQ(sn1.sessions[0].name, "a");
  EXPECT_EQ(sn1.sessions[2].name, "c");

  const NoiseRecordSet set = NoiseRecordsOfDevice(dir_.string(), "SN-1", procedure_);
  ASSERT_EQ(set.records.size(), 2u);
  EXPECT_EQ(set.records[0].label, "a");
  EXPECT_EQ(set.records[0].date, "2026-03-01");
  EXPECT_EQ(set.records[1].date, "2026-03-03");
  std::size_t replayed = 0;  // the source reads the session file again at each replay
  set.records[0].replay([&](const Sample*, std::size_t count) { replayed += count; });
  EXPECT_EQ(replayed, r.samples.size());
  ASSERT_EQ(set.notes.size(), 1u);
  EXPECT_TRUE(testing::Contains(set.notes[0], "session b has no record yet")) << set.notes[0];

  try {
    NoiseRecordsOfDevice(dir_.string(), "SN-9", procedure_);
    ADD_FAILURE() << "no error for an unknown device";
  } catch (const Error& e) {
    EXPECT_TRUE(testing::Contains(e.what(), "no noise record of device SN-9")) << e.what();
    EXPECT_TRUE(testing::Contains(e.what(), "SN-1 (3 sessions), SN-2 (1 session)")) << e.what();
  }
}

}  // namespace
}  // namespace accelcal::analysis
