// VirtualBench::SimulateRecording: the static poses of the plan as one continuous record, the
// way a person turns the sensor by hand from pose to pose.
#include <algorithm>
#include <cmath>

#include "accelcal/base/error.h"
#include "accelcal/acquire/sim/virtual_bench.h"

namespace accelcal::sim {
namespace {

// Amplitude of each of the three sinusoids that make up the hand jitter on one world axis,
// m/s^2. Under the sin(pi tau) envelope the jitter's RMS per axis is about 0.6 m/s^2, peaks
// near 1.5 m/s^2: an unsteady hand, well above the noise, as a segmenter will see it.
constexpr double kJitterAmplitudeMps2 = 0.6;
constexpr int kJitterTones = 3;

// Minimum-jerk profile: 0 -> 1 with zero velocity and acceleration at both ends.
double SmoothStep(double tau) { return tau * tau * tau * (10.0 - 15.0 * tau + 6.0 * tau * tau); }

struct JitterTone {
  double frequency_hz = 1.0;
  double phase_rad = 0.0;
};

// One stretch of the record: a pose held (from == to) or a move from one pose to the next.
struct Segment {
  double start_s = 0.0;
  double end_s = 0.0;
  Eigen::Quaterniond from;  // platform -> world at start
  Eigen::Quaterniond to;    // platform -> world at end
  bool is_move = false;
  JitterTone tones[3][kJitterTones];  // per world axis
  std::vector<ActivePulse> pulses;    // bumps of the pose held (holds only)
};

// Hand jitter during a move, world frame, m/s^2; zero at both ends of the move.
Eigen::Vector3d Jitter(const Segment& seg, double t_s) {
  const double tau = (t_s - seg.start_s) / (seg.end_s - seg.start_s);
  const double envelope = std::sin(M_PI * tau);
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < 3; ++axis) {
    for (const JitterTone& tone : seg.tones[axis]) {
      a(axis) +=
          kJitterAmplitudeMps2 * std::sin(2.0 * M_PI * tone.frequency_hz * t_s + tone.phase_rad);
    }
  }
  return envelope * a;
}

}  // namespace

std::vector<Sample> VirtualBench::SimulateRecording() {
  std::vector<Sample> all;
  SimulateRecording([&all](const std::vector<Sample>& chunk) {
    all.insert(all.end(), chunk.begin(), chunk.end());
  });
  return all;
}

void VirtualBench::SimulateRecording(const RecordingSink& sink, std::size_t chunk_samples) {
  if (chunk_samples == 0) throw Error("SimulateRecording: chunk_samples must be > 0");
  for (const CapturePlan& plan : scenario_.captures) {
    if (plan.kind != CaptureKind::kStatic) {
      throw Error(scenario_.source_name + ": capture '" + plan.label +
                  "' is a turntable capture; a continuous recording holds static poses only");
    }
  }
  Reseed(scenario_.bench.seed);
  const BenchSpec& bench = scenario_.bench;
  std::uniform_real_distribution<double> frequency_hz(0.8, 3.0);
  std::uniform_real_distribution<double> phase_rad(0.0, 2.0 * M_PI);

  std::vector<Segment> segments;
  double t_s = 0.0;
  Eigen::Quaterniond previous;
  for (int i = 0; i < static_cast<int>(scenario_.captures.size()); ++i) {
    // A pose's hold starts after the move to it; its bumps count from the start of the hold.
    const double hold_start_s = t_s + (i > 0 ? bench.move_s : 0.0);
    Mounting held = BeginCapture(i, hold_start_s);
    const Eigen::Quaterniond pose(held.platform_rotation);
    if (i > 0) {
      Segment move{t_s, hold_start_s, previous, pose, true, {}, {}};
      for (auto& axis_tones : move.tones) {
        for (JitterTone& tone : axis_tones) tone = {frequency_hz(rng_), phase_rad(rng_)};
      }
      segments.push_back(move);
      t_s = hold_start_s;
    }
    double hold_s = scenario_.CaptureDurationS(i);
    if (i == 0) hold_s = std::max(hold_s, bench.recording_quiet_start_s);
    segments.push_back(Segment{t_s, t_s + hold_s, pose, pose, false, {}, std::move(held.pulses)});
    t_s += hold_s;
    previous = pose;
  }
  session_duration_s_ = t_s;

  const double rate_hz = scenario_.sensor.rate_hz;
  const long n = std::lround(session_duration_s_ * rate_hz);
  const double g = bench.gravity_mps2;
  std::vector<Sample> samples;
  samples.reserve(std::min(static_cast<std::size_t>(std::max(n, 0L)), chunk_samples));
  std::size_t seg = 0;
  for (long k = 0; k < n; ++k) {
    const double ts = SampleTimeS(0.0, k, rate_hz);
    while (seg + 1 < segments.size() && ts >= segments[seg].end_s) ++seg;
    const Segment& s = segments[seg];
    Eigen::Vector3d f_world = g * Eigen::Vector3d::UnitZ();
    Eigen::Quaterniond q = s.from;
    if (s.is_move) {
      const double tau = std::clamp((ts - s.start_s) / (s.end_s - s.start_s), 0.0, 1.0);
      q = s.from.slerp(SmoothStep(tau), s.to);
      // The hand turns the sensor about itself, so the rotation adds no centripetal term of
      // note; the unsteadiness of the hand is the jitter.
      f_world += Jitter(s, ts);
    }
    for (const ActivePulse& p : s.pulses) f_world += p.AccelerationWorld(ts);
    samples.push_back(Measure(q.toRotationMatrix().transpose() * f_world, ts));
    if (samples.size() == chunk_samples) {
      sink(samples);
      samples.clear();
    }
  }
  if (!samples.empty()) sink(samples);
  session_duration_s_ = scenario_.SessionDurationS();
}

}  // namespace accelcal::sim
