#include "accelcal/acquire/static_detector.h"

#include <cmath>
#include <cstdio>
#include <cstdio>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/io/recording_reader.h"

namespace accelcal {
namespace {

constexpr double kRateHz = 100.0;

// Builds a synthetic 100 Hz recording: still poses joined by smooth hand-like moves, with
// 3 counts of white noise rounded to integer counts. Remembers where the poses really are.
class RecordingBuilder {
 public:
  struct Span {
    double t_start_s;
    double t_end_s;
  };

  explicit RecordingBuilder(const Eigen::Vector3d& start_pose) : pose_(start_pose) {}

  RecordingBuilder& Still(double duration_s) {
    const double t0 = Now();
    Append(duration_s, [&](double) { return pose_; });
    stills_.push_back({t0, Now() - 1.0 / kRateHz});
    return *this;
  }

  // A cosine-shaped move from the current pose to `to` (slow at both ends, as a hand is).
  RecordingBuilder& Move(double duration_s, const Eigen::Vector3d& to) {
    const Eigen::Vector3d from = pose_;
    Append(duration_s, [&](double u) {
      return Eigen::Vector3d(from + (to - from) * 0.5 * (1.0 - std::cos(M_PI * u)));
    });
    pose_ = to;
    return *this;
  }

  const std::vector<Sample>& samples() const { return samples_; }
  const std::vector<Span>& stills() const { return stills_; }

 private:
  double Now() const { return static_cast<double>(samples_.size()) / kRateHz; }

  template <typename Shape>
  void Append(double duration_s, Shape shape) {
    const int n = static_cast<int>(std::lround(duration_s * kRateHz));
    for (int i = 0; i < n; ++i) {
      Sample s;
      s.t_s = Now();
      const Eigen::Vector3d noise(noise_(rng_), noise_(rng_), noise_(rng_));
      s.raw_counts = (shape(static_cast<double>(i) / n) + noise).array().round();
      samples_.push_back(s);
    }
  }

  Eigen::Vector3d pose_;
  std::vector<Sample> samples_;
  std::vector<Span> stills_;
  std::mt19937 rng_{42};
  std::normal_distribution<double> noise_{0.0, 3.0};
};

StaticDetectorOptions ShortQuietStart() {
  StaticDetectorOptions options;
  options.init_static_s = 20.0;
  return options;
}

RecordingBuilder FivePoses() {
  RecordingBuilder b({33000, 33300, 36400});
  b.Still(25.0)
      .Move(3.0, {36400, 33300, 33000})
      .Still(6.0)
      .Move(4.0, {33000, 36400, 33300})
      .Still(8.0)
      .Move(2.5, {29600, 33300, 33000})
      .Still(5.0)
      .Move(3.0, {33000, 29600, 33300})
      .Still(4.0)
      .Move(2.0, {33500, 33000, 30000});
  return b;
}

std::string DetectionError(const std::vector<Sample>& recording,
                           const StaticDetectorOptions& options) {
  try {
    DetectStaticIntervals(recording, options);
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no Error";
  return "";
}

TEST(StaticDetector, FindsThePosesOfASyntheticRecording) {
  const RecordingBuilder b = FivePoses();
  const StaticDetection d = DetectStaticIntervals(b.samples(), ShortQuietStart());
  EXPECT_NEAR(d.quiet_variance_norm_counts2, std::sqrt(3.0) * 9.0, 1.5);  // 3 axes of 3^2
  EXPECT_DOUBLE_EQ(d.threshold_counts2, 6.0 * d.quiet_variance_norm_counts2);
  ASSERT_EQ(d.intervals.size(), b.stills().size());
  for (size_t i = 0; i < d.intervals.size(); ++i) {
    const StaticInterval& got = d.intervals[i];
    const RecordingBuilder::Span& truth = b.stills()[i];
    SCOPED_TRACE("interval " + std::to_string(i));
    // Inside the real pose, trimmed by at most about one window (1 s) at each end.
    EXPECT_GE(got.t_start_s, truth.t_start_s);
    EXPECT_LE(got.t_start_s, truth.t_start_s + 1.0);
    EXPECT_LE(got.t_end_s, truth.t_end_s);
    EXPECT_GE(got.t_end_s, truth.t_end_s - 1.0);
    EXPECT_DOUBLE_EQ(got.t_start_s, b.samples()[static_cast<size_t>(got.first_index)].t_s);
    EXPECT_DOUBLE_EQ(got.t_end_s, b.samples()[static_cast<size_t>(got.last_index)].t_s);
    EXPECT_GE(got.num_samples(), 100);
  }
  // The first window is complete only at sample 50: the first interval starts there.
  EXPECT_EQ(d.intervals.front().first_index, 50);
}

TEST(StaticDetector, DropsStaticRunsShorterThanTheMinimum) {
  RecordingBuilder b({0, 0, 4000});
  b.Still(25.0).Move(2.0, {4000, 0, 0}).Still(1.2).Move(2.0, {0, 4000, 0}).Still(5.0);
  StaticDetectorOptions options = ShortQuietStart();
  EXPECT_EQ(DetectStaticIntervals(b.samples(), options).intervals.size(), 2u);
  options.min_interval_samples = 10;  // the 1.2 s pose leaves a run of well under 100 samples
  EXPECT_EQ(DetectStaticIntervals(b.samples(), options).intervals.size(), 3u);
}

TEST(StaticDetector, CapturesFromIntervalsCopiesTheSamples) {
  const RecordingBuilder b = FivePoses();
  const StaticDetection d = DetectStaticIntervals(b.samples(), ShortQuietStart());
  const std::vector<Capture> captures = CapturesFromIntervals(b.samples(), d);
  ASSERT_EQ(captures.size(), d.intervals.size());
  for (size_t i = 0; i < captures.size(); ++i) {
    const Capture& c = captures[i];
    const StaticInterval& interval = d.intervals[i];
    EXPECT_EQ(c.id, static_cast<int>(i) + 1);
    EXPECT_EQ(c.kind, CaptureKind::kStatic);
    EXPECT_TRUE(c.used());
    ASSERT_EQ(static_cast<long>(c.samples.size()), interval.num_samples());
    EXPECT_EQ(c.samples.front().t_s, interval.t_start_s);
    EXPECT_EQ(c.samples.back().raw_counts,
              b.samples()[static_cast<size_t>(interval.last_index)].raw_counts);
  }
  char expected[64];
  std::snprintf(expected, sizeof expected, "static %.1f-%.1f s", d.intervals[0].t_start_s,
                d.intervals[0].t_end_s);
  EXPECT_EQ(captures[0].label, expected);
  EXPECT_EQ(captures[0].label.rfind("static 0.5-24.", 0), 0u) << captures[0].label;
}

TEST(StaticDetector, RecordingShorterThanTheQuietStart) {
  RecordingBuilder b({0, 0, 4000});
  b.Still(10.0);
  const std::string message = DetectionError(b.samples(), ShortQuietStart());
  EXPECT_NE(message.find("shorter than its quiet start (init_static_s = 20 s)"), std::string::npos)
      << message;
}

TEST(StaticDetector, QuietStartThatIsNotQuiet) {
  // Moves from the first second: the "quiet" start holds three of them.
  RecordingBuilder b({0, 0, 4000});
  b.Still(1.0).Move(3.0, {4000, 0, 0}).Still(5.0).Move(3.0, {0, 4000, 0}).Still(4.0)
      .Move(3.0, {0, 0, 4000});
  for (int i = 0; i < 10; ++i) b.Still(8.0);  // mostly still afterwards: a low median
  const std::string message = DetectionError(b.samples(), ShortQuietStart());
  EXPECT_NE(message.find("the quiet start (first 20 s) is not quiet"), std::string::npos)
      << message;
}

TEST(StaticDetector, NoiseFreeQuietStartGivesNoThreshold) {
  std::vector<Sample> recording(3000);
  for (size_t i = 0; i < recording.size(); ++i) {
    recording[i].t_s = static_cast<double>(i) / kRateHz;
    recording[i].raw_counts = {1, 2, 3};
  }
  const std::string message = DetectionError(recording, ShortQuietStart());
  EXPECT_NE(message.find("zero variance"), std::string::npos) << message;
}

TEST(StaticDetector, TooFewSamplesForOneWindow) {
  std::vector<Sample> recording(50);
  for (size_t i = 0; i < recording.size(); ++i) recording[i].t_s = static_cast<double>(i);
  const std::string message = DetectionError(recording, ShortQuietStart());
  EXPECT_NE(message.find("fewer than one window"), std::string::npos) << message;
}

TEST(StaticDetector, OptionsAreValidated) {
  EXPECT_EQ(StaticDetectorOptions{}.Validate(), "");
  StaticDetectorOptions options;
  options.window_samples = 100;
  EXPECT_NE(options.Validate().find("odd"), std::string::npos);
  options = {};
  options.threshold_multiplier = 0.0;
  EXPECT_NE(options.Validate(), "");
  options = {};
  options.init_static_s = -1.0;
  EXPECT_NE(options.Validate(), "");
  options = {};
  options.min_interval_samples = 0;
  EXPECT_NE(options.Validate(), "");
  EXPECT_THROW(DetectStaticIntervals(FivePoses().samples(), options), Error);
}

class StaticDetectorImuTk : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string path = std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/imu_tk/xsens_acc.mat";
    recording_ = ReadRecordingFile(path);
  }
  std::vector<Sample> recording_;
};

TEST_F(StaticDetectorImuTk, DefaultsFindTheReference38Intervals) {
  const StaticDetection d = DetectStaticIntervals(recording_, StaticDetectorOptions{});
  // imu_tk: 6 x 18.93 = 113.59 counts^2.
  EXPECT_NEAR(d.quiet_variance_norm_counts2, 18.93, 0.01);
  EXPECT_NEAR(d.threshold_counts2, 113.59, 0.05);
  ASSERT_EQ(d.intervals.size(), 38u);
  EXPECT_NEAR(d.intervals.front().t_start_s, 0.53, 0.01);
  EXPECT_NEAR(d.intervals.front().t_end_s, 51.92, 0.01);
  for (const StaticInterval& interval : d.intervals) {
    EXPECT_GE(interval.num_samples(), 100);
    EXPECT_LT(interval.t_start_s, interval.t_end_s);
  }
  for (size_t i = 1; i < d.intervals.size(); ++i) {
    EXPECT_GT(d.intervals[i].first_index, d.intervals[i - 1].last_index + 1);
  }
  EXPECT_EQ(CapturesFromIntervals(recording_, d).size(), 38u);
}

TEST_F(StaticDetectorImuTk, CountIsStableAcrossMultipliersFiveToTen) {
  // The plateau the header comment cites when it explains the default multiplier.
  for (double k = 5.0; k <= 10.0; k += 1.0) {
    StaticDetectorOptions options;
    options.threshold_multiplier = k;
    EXPECT_EQ(DetectStaticIntervals(recording_, options).intervals.size(), 38u) << "k = " << k;
  }
  StaticDetectorOptions low;
  low.threshold_multiplier = 3.0;
  EXPECT_EQ(DetectStaticIntervals(recording_, low).intervals.size(), 40u);
}

}  // namespace
}  // namespace accelcal
