// `accelcal noise`: the inherent-noise analysis of a device's noise records (sessions of the
// noise procedure in the store) or of recording files: per-axis std, noise density, normality,
// spectrum, and the day-to-day change of the mean.
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include <fmt/core.h>

#include "accelcal/analysis/noise_analysis.h"
#include "accelcal/app/calibration_input.h"
#include "accelcal/app/noise_records.h"
#include "accelcal/bags/bag_open.h"
#include "accelcal/base/error.h"
#include "accelcal/io/noise_file.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/report/noise_text.h"
#include "accelcal/session/session_paths.h"
#include "accelcal/session/procedure.h"
#include "cli/cli_checks.h"
#include "cli/commands.h"
#include "cli/output.h"
#include "cli/sample_format_flags.h"
#include "cli/shipped_files.h"

namespace accelcal::cli {
namespace {

struct NoiseCommandOptions {
  std::string device;                  // serial; or empty with record_paths
  std::vector<std::string> record_paths;  // --record FILE...
  std::string sessions_dir;            // empty: the default directory
  std::string procedure_path;          // empty: procedures/noise.toml of the source tree
  std::string calibration_path;        // empty: counts
  std::string output_format = "text";  // text | json
  std::string output_path;             // empty: stdout
  SampleFormatFlags format;            // --record files
};

// What the reading of each --record file understood: known after the analysis's first pass.
struct FileReadings {
  std::vector<std::unique_ptr<ReadingSummary>> summaries;
};

// A bag's readings are m/s^2 already (sensor_msgs/Imu): without a calibration they are analysed
// as recorded, through a calibration of unit scale (a^p = the readings), and the output says so.
// Text files with bags need one unit: counts and m/s^2 are not mixed.
std::optional<Calibration> AsRecordedForBags(const NoiseCommandOptions& o) {
  std::vector<std::string> bags, texts;
  for (const std::string& path : o.record_paths)
    (bags::DetectBag(path) ? bags : texts).push_back(path);
  if (bags.empty()) return std::nullopt;
  if (!texts.empty())
    throw Error(fmt::format("--record: {} is a bag (m/s^2) and {} is not: give the --calibration "
                            "of the sensor, or analyse them apart", bags.front(), texts.front()));
  SampleFormat format = o.format.Resolve();
  Calibration as_recorded;
  as_recorded.reading_unit = ReadingUnit{ReadingUnit::Kind::kMps2, format.unit.is_counts()
                                                                       ? ReadingUnit::kDefaultCountsPerUnit
                                                                       : format.unit.counts_per_unit};
  as_recorded.model.scale_counts_per_mps2 =
      Eigen::Vector3d::Constant(as_recorded.reading_unit.counts_per_unit);
  as_recorded.source = "none: the bag's linear_acceleration as recorded";
  return as_recorded;
}

std::vector<analysis::NoiseRecordSource> Records(const NoiseCommandOptions& o,
                                                 const std::optional<Calibration>& calibration,
                                                 FileReadings* readings,
                                                 std::vector<std::string>* notes) {
  std::vector<analysis::NoiseRecordSource> records;
  if (!o.record_paths.empty()) {
    SampleFormat format = o.format.Resolve();
    if (calibration) {
      if (format.unit_declared && format.unit.Describe() != calibration->reading_unit.Describe())
        throw Error(fmt::format("--unit {}: the calibration was made from readings in {}",
                                format.unit.Describe(), calibration->reading_unit.Describe()));
      format.unit = calibration->reading_unit;
      format.unit_declared = true;
    } else if (!format.unit.is_counts()) {
      throw Error(fmt::format("--unit {}: the noise analysis is in counts, or in m/s^2 with the "
                              "--calibration made from the same logger's readings",
                              format.unit.Name()));
    }
    for (const std::string& path : o.record_paths) {
      readings->summaries.push_back(std::make_unique<ReadingSummary>());
      records.push_back(
          analysis::NoiseRecordFromFile(path, format, readings->summaries.back().get()));
    }
    return records;
  }
  const Procedure procedure = LoadProcedure(
      o.procedure_path.empty() ? ShippedProcedurePath("noise.toml") : o.procedure_path);
  const std::string dir = o.sessions_dir.empty() ? DefaultSessionDir() : o.sessions_dir;
  analysis::NoiseRecordSet set = analysis::NoiseRecordsOfDevice(dir, o.device, procedure);
  *notes = std::move(set.notes);
  return std::move(set.records);
}

void RunNoise(const NoiseCommandOptions& o) {
  if (o.device.empty() == o.record_paths.empty())
    throw Error("give either a DEVICE serial or --record FILE..., not both");
  std::optional<Calibration> calibration;
  if (!o.calibration_path.empty()) calibration = ReadCalibrationInput(o.calibration_path).calibration;
  else calibration = AsRecordedForBags(o);
  std::vector<std::string> notes;
  FileReadings readings;
  const std::vector<analysis::NoiseRecordSource> records =
      Records(o, calibration, &readings, &notes);
  analysis::NoiseReport report = analysis::AnalyzeNoiseSources(
      records, analysis::NoiseAnalysisOptions{}, calibration ? &*calibration : nullptr);
  // What was understood goes to stderr: the report (stdout or -o) stays the analysis.
  std::vector<std::string> file_notes;
  for (const auto& summary : readings.summaries) {
    fmt::print(stderr, "accelcal: read {}\n", summary->Describe());
    if (!summary->converted_hint.empty()) file_notes.push_back(summary->converted_hint);
  }
  notes.insert(notes.begin(), file_notes.begin(), file_notes.end());
  report.warnings.insert(report.warnings.begin(), notes.begin(), notes.end());
  if (o.output_format == "json") {
    WriteOutputText(o.output_path, NoiseFileText(report));
  } else {
    std::string header = o.device.empty() ? "" : fmt::format("Device {}\n", o.device);
    WriteOutputText(o.output_path, header + FormatNoiseText(report));
  }
}

}  // namespace

void SetupNoiseCommand(CLI::App& app) {
  auto opts = std::make_shared<NoiseCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "noise",
      "Inherent noise of a device from its 1-minute static records (sessions of the noise\n"
      "procedure, one per day): per axis the mean, standard deviation, noise density (Welch\n"
      "PSD, flat band), a normality check (Jarque-Bera) and the spectrum (JSON), and the\n"
      "day-to-day change of the mean (turn-on bias repeatability, 3 days or more). Units:\n"
      "counts, or m/s^2 with --calibration.\n\n"
      "Examples:\n"
      "  accelcal noise SN-1234\n"
      "  accelcal noise SN-1234 --sessions-dir /mnt/bench/sessions --format json -o noise.json\n"
      "  accelcal noise --record day1.txt day2.txt day3.txt --calibration cal.json");
  sub->add_option("device", opts->device, "Device serial (as recorded in its sessions)");
  sub->add_option("--record", opts->record_paths,
                  "Recording files (t ax ay az [temp_c]) or ROS bags (--topic; m/s^2 as recorded "
                  "without --calibration) instead of sessions; undated")
      ->check(InputFileOrBag());
  sub->add_option("--sessions-dir", opts->sessions_dir,
                  "Session directory (default: $XDG_DATA_HOME/accelcal/sessions)");
  sub->add_option("--procedure", opts->procedure_path,
                  "The noise procedure whose sessions count (default: procedures/noise.toml)")
      ->transform(ShippedFile(kShippedProcedures));
  sub->add_option("--calibration", opts->calibration_path,
                  "Calibration file (JSON) or a calibrated session: results in m/s^2 instead of counts");
  opts->format.Bind(*sub, "the --record files");
  sub->add_option("--format", opts->output_format, "text or json")
      ->check(CLI::IsMember({"text", "json"}))->capture_default_str();
  sub->add_option("-o,--output", opts->output_path, "Write here instead of standard output");
  sub->callback([opts] { RunNoise(*opts); });
}

}  // namespace accelcal::cli
