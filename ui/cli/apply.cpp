// `accelcal apply`: raw sample lines in, calibrated m/s^2 out.
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include "accelcal/calibration/apply.h"
#include "accelcal/base/error.h"
#include "accelcal/io/calibration_file.h"
#include "cli/cli_checks.h"
#include "cli/commands.h"
#include "cli/sample_format_flags.h"

namespace accelcal::cli {
namespace {

struct ApplyCommandOptions {
  std::string calibration_path;
  int max_reported = 20;
  SampleFormatFlags format;
};

void RunApply(const ApplyCommandOptions& o) {
  const Calibration cal = ReadCalibrationFile(o.calibration_path);
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
  const ApplyStreamResult r = ApplyStream(
      std::cin, std::cout, applier, "<stdin>",
      [&](const InputError& e) {
        if (reported++ < o.max_reported) fmt::print(stderr, "accelcal: skipped {}\n", e.what());
      },
      format, &summary);
  std::cout.flush();
  fmt::print(stderr, "accelcal: read {}\n", summary.Describe());
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
      "blanks, commas or semicolons; or the columns a header row or --columns names) on standard\n"
      "input and writes 't ax ay az [temp_c]' in m/s^2 on standard output. Malformed lines are\n"
      "reported on stderr and skipped (exit status 1).\n\n"
      "Example:\n"
      "  accelcal apply cal.json < raw.txt > calibrated.txt");
  sub->add_option("calibration", opts->calibration_path, "Calibration file (JSON) from 'accelcal fit'")
      ->required()
      ->check(InputFile());
  opts->format.Bind(*sub, "standard input");
  sub->add_option("--max-reported", opts->max_reported, "Malformed lines reported one by one at most")
      ->capture_default_str();
  sub->callback([opts] { RunApply(*opts); });
}

}  // namespace accelcal::cli
