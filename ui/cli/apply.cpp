// `accelcal apply`: raw samples in (standard input, a recording file, or a ROS bag's IMU topic),
// calibrated m/s^2 lines out.
#include <fstream>
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include "accelcal/app/calibration_input.h"
#include "accelcal/bags/bag_open.h"
#include "accelcal/calibration/apply.h"
#include "accelcal/base/error.h"
#include "accelcal/io/recording_stream.h"
#include "cli/cli_checks.h"
#include "cli/commands.h"
#include "cli/sample_format_flags.h"

namespace accelcal::cli {
namespace {

struct ApplyCommandOptions {
  std::string calibration_input;  // a calibration file or a session (app/calibration_input.h)
  int sensor = 1;                 // --sensor N of a several-sensor session (1-based)
  std::string input_path;  // empty: standard input
  int max_reported = 20;
  SampleFormatFlags format;
};

// A bag's IMU topic: its samples (m/s^2, read as the calibration's unit says) written as the
// lines of text input are; a message whose value cannot be given is reported and skipped.
ApplyStreamResult ApplyBag(const ApplyCommandOptions& o, const CalibrationApplier& applier,
                           SampleFormat format, ReadingSummary* summary) {
  if (applier.needs_temperature())
    throw Error(fmt::format("{}: this calibration corrects for temperature, and sensor_msgs/Imu "
                            "carries none", o.input_path));
  format.unit = applier.reading_unit();
  format.unit_declared = true;
  RecordingStream stream(o.input_path, RecordingStream::kDefaultBlockBytes, format);
  CalibratedLineWriter writer(std::cout, applier);
  ApplyStreamResult result;
  std::vector<Sample> block;
  std::string why;
  while (stream.Next(&block)) {
    for (const Sample& s : block) {
      ++result.lines;
      if (writer.Write(s, &why)) {
        ++result.samples;
      } else if (result.malformed++ < o.max_reported) {
        fmt::print(stderr, "accelcal: skipped {}: sample {}: {}\n", o.input_path, result.lines, why);
      }
    }
  }
  *summary = stream.Summary();
  return result;
}

void RunApply(const ApplyCommandOptions& o) {
  const Calibration cal = ReadCalibrationInput(o.calibration_input, o.sensor - 1).calibration;
  const SampleFormat format = o.format.Resolve();
  if (format.unit_declared && format.unit.Describe() != cal.reading_unit.Describe())
    throw Error(fmt::format("--unit {}: the calibration was made from readings in {}; apply reads "
                            "readings as it was made", format.unit.Describe(),
                            cal.reading_unit.Describe()));
  const CalibrationApplier applier(cal);
  for (const std::string& n : applier.not_applied())
    fmt::print(stderr, "accelcal: note: not applied to readings: {}\n", n);
  std::ios::sync_with_stdio(false);
  long reported = 0;
  ReadingSummary summary;
  ApplyStreamResult r;
  if (!o.input_path.empty() && bags::DetectBag(o.input_path)) {
    r = ApplyBag(o, applier, format, &summary);
  } else {
    if (!format.bag.topic.empty() || format.bag.receive_time)
      throw Error(fmt::format("--topic and --bag-time are for a ROS bag; {} is not one",
                              o.input_path.empty() ? "standard input" : o.input_path));
    std::ifstream file;
    if (!o.input_path.empty()) {
      file.open(o.input_path, std::ios::binary);
      if (!file) throw Error(fmt::format("cannot open '{}'", o.input_path));
    }
    std::istream& in = o.input_path.empty() ? std::cin : file;
    r = ApplyStream(
        in, std::cout, applier, o.input_path.empty() ? "<stdin>" : o.input_path,
        [&](const InputError& e) {
          if (reported++ < o.max_reported) fmt::print(stderr, "accelcal: skipped {}\n", e.what());
        },
        format, &summary);
  }
  std::cout.flush();
  fmt::print(stderr, "accelcal: read {}\n", summary.Describe());
  if (!std::cout) throw Error("cannot write the calibrated samples to standard output");
  if (r.malformed > 0)
    throw Error(fmt::format("{} of {} {} were malformed and skipped ({} shown above); {} "
                            "samples written", r.malformed, r.lines,
                            summary.origin.empty() ? "lines" : "samples",
                            std::min<long>(r.malformed, o.max_reported), r.samples));
}

}  // namespace

void SetupApplyCommand(CLI::App& app) {
  auto opts = std::make_shared<ApplyCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "apply",
      "Apply a calibration (a file, or a session's) to raw samples: reads lines 't ax ay az [temp_c]' (raw counts,\n"
      "blanks, commas or semicolons; or the columns a header row or --columns names) on standard\n"
      "input or from INPUT, and writes 't ax ay az [temp_c]' in m/s^2 on standard output.\n"
      "INPUT may be a ROS bag (.bag, .mcap, .db3, a ROS 2 bag folder): its IMU topic's\n"
      "linear_acceleration (--topic), t from the header stamps, written as the same text lines\n"
      "(the bag is not rewritten). Malformed lines are reported on stderr and skipped (exit\n"
      "status 1).\n\n"
      "Examples:\n"
      "  accelcal apply cal.json < raw.txt > calibrated.txt\n"
      "  accelcal apply bench.db --sensor 3 raw3.txt > calibrated3.txt\n"
      "  accelcal apply cal.json imu.mcap --topic /imu/data > calibrated.txt");
  sub->add_option("calibration", opts->calibration_input,
                  "Calibration file (JSON, from 'accelcal fit' or 'report --format calibration') or session")
      ->required();
  sub->add_option("--sensor", opts->sensor, "Which sensor of a several-sensor session (1-based)")
      ->check(CLI::PositiveNumber)->capture_default_str();
  sub->add_option("input", opts->input_path,
                  "Samples to calibrate: a recording file or a ROS bag (default: standard input)")
      ->check(InputFileOrBag());
  opts->format.Bind(*sub, "the input");
  sub->add_option("--max-reported", opts->max_reported, "Malformed lines reported one by one at most")
      ->capture_default_str();
  sub->callback([opts] { RunApply(*opts); });
}

}  // namespace accelcal::cli
