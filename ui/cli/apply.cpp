// `accelcal apply`: raw sample lines in, calibrated m/s^2 out.
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include "accelcal/calibration/apply.h"
#include "accelcal/base/error.h"
#include "accelcal/io/calibration_file.h"
#include "cli/commands.h"

namespace accelcal::cli {
namespace {

struct ApplyCommandOptions {
  std::string calibration_path;
  int max_reported = 20;
};

void RunApply(const ApplyCommandOptions& o) {
  const Calibration cal = ReadCalibrationFile(o.calibration_path);
  const CalibrationApplier applier(cal);
  for (const std::string& n : applier.not_applied())
    fmt::print(stderr, "accelcal: note: not applied to readings: {}\n", n);
  std::ios::sync_with_stdio(false);
  long reported = 0;
  const ApplyStreamResult r =
      ApplyStream(std::cin, std::cout, applier, "<stdin>", [&](const InputError& e) {
        if (reported++ < o.max_reported) fmt::print(stderr, "accelcal: skipped {}\n", e.what());
      });
  std::cout.flush();
  if (!std::cout) throw Error("cannot write the calibrated samples to standard output");
  if (r.malformed > 0)
    throw Error(fmt::format("{} of {} lines were malformed and skipped ({} shown above); {} "
                            "samples written", r.malformed, r.lines,
                            std::min<long>(r.malformed, o.max_reported), r.samples));
}

}  // namespace

void SetupApplyCommand(CLI::App& app) {
  auto opts = std::make_shared<ApplyCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "apply",
      "Apply a calibration file to raw samples: reads lines 't ax ay az [temp_c]' (raw counts,\n"
      "blanks or commas) on standard input and writes 't ax ay az [temp_c]' in m/s^2 on standard\n"
      "output. Malformed lines are reported on stderr and skipped (exit status 1).\n\n"
      "Example:\n"
      "  accelcal apply cal.json < raw.txt > calibrated.txt");
  sub->add_option("calibration", opts->calibration_path, "Calibration file (JSON) from 'accelcal fit'")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("--max-reported", opts->max_reported, "Malformed lines reported one by one at most")
      ->capture_default_str();
  sub->callback([opts] { RunApply(*opts); });
}

}  // namespace accelcal::cli
