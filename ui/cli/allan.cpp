// `accelcal allan`: the Allan deviation and the IEEE 952 read-offs of a long static record.
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include <fmt/core.h>

#include "accelcal/app/analyze_recording.h"
#include "accelcal/app/calibration_input.h"
#include "accelcal/base/error.h"
#include "accelcal/io/export/kalibr_imu_yaml.h"
#include "accelcal/io/allan_file.h"
#include "accelcal/io/atomic_write.h"
#include "accelcal/report/allan_text.h"
#include "cli/cli_checks.h"
#include "cli/commands.h"
#include "cli/sample_format_flags.h"

namespace accelcal::cli {
namespace {

struct AllanCommandOptions {
  std::string recording_path;   // a recording file, or a session file holding a record
  std::string step;             // the session's record step; empty: its only (or first) one
  std::string calibration_path;  // a calibration file or a session (app/calibration_input.h); empty: counts
  std::string output_path;       // allan.json; empty: none
  std::string kalibr_path;       // imu.yaml; empty: none
  double drift_window_s = 60.0;
  SampleFormatFlags format;      // recording files (its --rate-hz is the analysis's rate too)
};

// Kalibr's imu.yaml from the analysis: the worst axis of each figure (Kalibr takes one).
void WriteKalibr(const AllanCommandOptions& o, const std::string& allan_text, const Calibration& cal) {
  const AllanNoiseFigures f = AllanNoiseForKalibrText(allan_text, cal, o.recording_path);
  if (!std::isfinite(f.noise_density_mps2_per_sqrt_hz) || !std::isfinite(f.random_walk_mps3_per_sqrt_hz))
    throw Error("--kalibr: the record gives no noise density or random walk (too short?)");
  KalibrImuYamlOptions k;
  k.accelerometer_noise_density = f.noise_density_mps2_per_sqrt_hz;
  k.accelerometer_random_walk = f.random_walk_mps3_per_sqrt_hz;
  k.update_rate_hz = f.rate_hz;
  k.comment = fmt::format("accelcal allan {}: noise density from axis {}, random walk from axis {} "
                          "(the largest)", o.recording_path, f.noise_density_axis, f.random_walk_axis);
  const ExportResult r = WriteKalibrImuYaml(k);
  WriteFileAtomically(o.kalibr_path, r.text);
  std::cout << fmt::format("Kalibr imu.yaml written to {}\n", o.kalibr_path);
  for (const std::string& c : r.cannot_hold) std::cout << fmt::format("  note: {}\n", c);
}

void RunAllan(const AllanCommandOptions& o) {
  RecordAnalysisOptions options;
  const SampleFormat format = o.format.Resolve();
  options.rate_hz = format.rate_hz;
  options.drift.window_s = o.drift_window_s;
  std::optional<Calibration> cal;
  if (!o.calibration_path.empty()) cal = ReadCalibrationInput(o.calibration_path).calibration;
  if (!o.kalibr_path.empty() && !cal)
    throw Error("--kalibr: Kalibr wants m/s^2; give the sensor's --calibration");
  const RecordInputAnalysis in = AnalyzeRecordInput(o.recording_path, o.step, options, cal, format);
  if (in.reading) {
    std::cout << "read " << in.reading->Describe() << "\n";
    if (!in.reading->converted_hint.empty()) std::cout << "note: " << in.reading->converted_hint << "\n";
  }
  const RecordAnalysis& analysis = in.analysis;
  const std::string& source = in.source;
  if (analysis.samples < 2)
    throw Error(fmt::format("{}: {} samples: nothing to analyse", source, analysis.samples));
  const std::string allan = AllanFileText(analysis, source, o.drift_window_s);
  std::cout << FormatAllanText(analysis, source);
  if (!o.output_path.empty()) {
    WriteAllanFile(o.output_path, allan);
    std::cout << fmt::format("\nAllan analysis written to {}\n", o.output_path);
  }
  if (!o.kalibr_path.empty()) WriteKalibr(o, allan, *cal);
}

}  // namespace

void SetupAllanCommand(CLI::App& app) {
  auto opts = std::make_shared<AllanCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "allan",
      "Overlapping Allan deviation of a long static record (the drift procedure's, any\n"
      "recording 't ax ay az [temp_c]', or a ROS bag's IMU topic: .bag, .mcap, .db3, a ROS 2\n"
      "bag folder, in m/s^2), with 68.3 % confidence bounds, and the IEEE 952\n"
      "read-offs per axis: noise density (slope -1/2 at 1 s), bias instability (minimum /\n"
      "0.664), random walk (slope +1/2 at 3 s), and the drift of 1-minute means. In raw counts,\n"
      "or in m/s^2 with a calibration file. Streams the file: any length in bounded memory.\n\n"
      "Examples:\n"
      "  accelcal allan drift.txt\n"
      "  accelcal allan drift.txt --calibration cal.json -o allan.json\n"
      "  accelcal allan drift-session.db -o allan.json      # a wizard session's record\n"
      "  accelcal allan imu.bag --topic /imu -o allan.json   # a ROS bag");
  sub->add_option("recording", opts->recording_path,
                  "Recording file ('-': standard input), a ROS bag, or a session file holding a record")
      ->required();
  sub->add_option("--step", opts->step, "The session's record step (default: its first record)");
  sub->add_option("--calibration", opts->calibration_path,
                  "Calibration file, or a finished session: figures in m/s^2 instead of counts")
      ->check(InputFile());
  sub->add_option("-o,--output", opts->output_path, "Write the analysis (allan.json) here");
  sub->add_option("--kalibr", opts->kalibr_path,
                  "Also write Kalibr's imu.yaml (needs --calibration: Kalibr wants m/s^2)");
  opts->format.Bind(*sub, "the recording");
  sub->add_option("--drift-window-s", opts->drift_window_s, "Window of the drift means, s")
      ->check(Positive())->capture_default_str();
  sub->callback([opts] { RunAllan(*opts); });
}

}  // namespace accelcal::cli
