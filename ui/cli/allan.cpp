// `accelcal allan`: the Allan deviation and the IEEE 952 read-offs of a long static record.
#include <iostream>
#include <memory>
#include <optional>

#include <fmt/core.h>

#include "accelcal/analysis/analyze_recording.h"
#include "accelcal/error.h"
#include "accelcal/io/allan_file.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/report/allan_text.h"
#include "cli/commands.h"

namespace accelcal::cli {
namespace {

struct AllanCommandOptions {
  std::string recording_path;
  std::string calibration_path;  // empty: figures in counts
  std::string output_path;       // allan.json; empty: none
  double rate_hz = kNaN;         // NaN: from the time stamps
  double drift_window_s = 60.0;
};

void RunAllan(const AllanCommandOptions& o) {
  std::optional<Calibration> cal;
  if (!o.calibration_path.empty()) cal = ReadCalibrationFile(o.calibration_path);
  RecordAnalysisOptions options;
  options.rate_hz = o.rate_hz;
  options.drift.window_s = o.drift_window_s;
  const RecordAnalysis analysis = AnalyzeRecordingFile(o.recording_path, options, cal);
  if (analysis.samples < 2)
    throw Error(fmt::format("{}: {} samples: nothing to analyse", o.recording_path, analysis.samples));
  const nlohmann::json allan = RecordAnalysisToJson(analysis, o.recording_path, o.drift_window_s);
  std::cout << FormatAllanText(allan);
  if (!o.output_path.empty()) {
    WriteAllanFile(o.output_path, allan);
    std::cout << fmt::format("\nAllan analysis written to {}\n", o.output_path);
  }
}

}  // namespace

void SetupAllanCommand(CLI::App& app) {
  auto opts = std::make_shared<AllanCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "allan",
      "Overlapping Allan deviation of a long static record (the drift procedure's, or any\n"
      "recording 't ax ay az [temp_c]'), with 68.3 % confidence bounds, and the IEEE 952\n"
      "read-offs per axis: noise density (slope -1/2 at 1 s), bias instability (minimum /\n"
      "0.664), random walk (slope +1/2 at 3 s), and the drift of 1-minute means. In raw counts,\n"
      "or in m/s^2 with a calibration file. Streams the file: any length in bounded memory.\n\n"
      "Examples:\n"
      "  accelcal allan drift.txt\n"
      "  accelcal allan drift.txt --calibration cal.json -o allan.json");
  sub->add_option("recording", opts->recording_path, "Recording file ('-': standard input)")
      ->required();
  sub->add_option("--calibration", opts->calibration_path,
                  "Calibration file: figures in m/s^2 instead of counts")
      ->check(CLI::ExistingFile);
  sub->add_option("-o,--output", opts->output_path, "Write the analysis (allan.json) here");
  sub->add_option("--rate-hz", opts->rate_hz,
                  "Sample rate, Hz (default: the median interval of the first samples)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--drift-window-s", opts->drift_window_s, "Window of the drift means, s")
      ->check(CLI::PositiveNumber)->capture_default_str();
  sub->callback([opts] { RunAllan(*opts); });
}

}  // namespace accelcal::cli
