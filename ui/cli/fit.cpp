// `accelcal fit`: the nine calibration parameters from a capture set or a continuous recording.
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include "accelcal/app/calibration_pipeline.h"
#include "accelcal/base/error.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/io/capture_set_reader.h"
#include "accelcal/io/recording_reader.h"
#include "accelcal/acquire/static_detector.h"
#include "accelcal/report/report_model.h"
#include "cli/cli_checks.h"
#include "cli/commands.h"
#include "accelcal/report/fit_text.h"
#include "cli/gravity_options.h"
#include "cli/sample_format_flags.h"

namespace accelcal::cli {
namespace {

struct FitCommandOptions {
  std::string captures_path;
  std::string recording_path;
  std::string output_path;
  std::vector<double> adc_range;
  int min_samples = ScreeningOptions{}.min_samples;
  StaticDetectorOptions detector;
  bool no_stability_check = false;
  std::vector<double> noise_floor;  // counts per axis; empty: estimated from the set
  bool quiet = false;
  bool no_diagnose = false;
  GravityFlags gravity;
  SampleFormatFlags format;  // recordings
};

struct LoadedCaptures {
  std::vector<Capture> captures;
  std::string source;
  std::optional<AdcRange> adc_range;
  std::string intervals_text;  // for recordings: the intervals found
  std::string reading_text;    // for recordings: what the reader understood, one line
  ReadingUnit reading_unit;
};

LoadedCaptures LoadCaptureSet(const FitCommandOptions& o) {
  CaptureSet set = ReadCaptureSetFile(o.captures_path);
  return {std::move(set.captures), o.captures_path, set.adc_range, {}, {}, {}};
}

LoadedCaptures LoadRecording(const FitCommandOptions& o) {
  if (std::string e = o.detector.Validate(); !e.empty()) throw Error("static detector: " + e);
  const SampleFormat format = o.format.Resolve();
  const Recording recording = ReadRecording(o.recording_path, format);
  if (!recording.summary.converted_hint.empty())
    throw Error(fmt::format("{}: {}", o.recording_path, recording.summary.converted_hint));
  const StaticDetection detection = DetectStaticIntervals(recording.samples, o.detector);
  // The unit as read: the format's, or a bag's m/s^2.
  const ReadingUnit& unit = recording.summary.unit;
  LoadedCaptures out{CapturesFromIntervals(recording.samples, detection), o.recording_path,
                     std::nullopt, FormatIntervals(detection, o.detector),
                     "read " + recording.summary.Describe() + "\n", unit};
  if (!unit.is_counts())
    out.reading_text += fmt::format(
        "readings in {0}: the model's counts are {1} {0} here, so bias_counts is in those "
        "counts and a scale of {2} counts per {0} means the {3} own conversion is exact\n",
        unit.Name(), 1.0 / unit.counts_per_unit, unit.counts_per_unit,
        recording.summary.origin.empty() ? "logger's" : "IMU driver's");
  return out;
}

void RunFit(const FitCommandOptions& o) {
  const GravitySpec gravity = o.gravity.Resolve();
  LoadedCaptures loaded = o.recording_path.empty() ? LoadCaptureSet(o) : LoadRecording(o);

  CalibrationRequest request;
  request.captures = std::move(loaded.captures);
  request.source_name = loaded.source;
  request.gravity = gravity;
  request.screening.min_samples = o.min_samples;
  request.screening.adc_range = loaded.adc_range;
  if (o.adc_range.size() == 2) request.screening.adc_range = AdcRange{o.adc_range[0], o.adc_range[1]};
  // Recordings' intervals are already static by the detector's own test; a capture set's
  // captures get the static stability check here.
  if (o.recording_path.empty() && !o.no_stability_check) {
    OfflineStabilityOptions stability;
    if (o.noise_floor.size() == 3) {
      stability.noise_floor_counts = Eigen::Vector3d(o.noise_floor[0], o.noise_floor[1],
                                                     o.noise_floor[2]);
    }
    request.stability = stability;
  }
  request.diagnose = !o.no_diagnose;
  request.reading_unit = loaded.reading_unit;
  // The gravity's uncertainty is known here (the bench's radius and speed are not): the budget
  // holds it, and says what it lacks.
  request.references = ReferenceUncertainties{};
  const CalibrationOutcome outcome = CalibrateCaptures(std::move(request));
  const FitSummary& summary = outcome.Fit(true);

  if (!o.quiet) {
    std::cout << fmt::format("source: {}\ngravity: {}\n", loaded.source, gravity.Describe());
    std::cout << loaded.reading_text << loaded.intervals_text;
  }
  if (!summary.IsUsable()) {
    if (!o.quiet) std::cout << FormatCaptureTable(outcome.captures, summary);
    throw Error(fmt::format("no calibration: {}", summary.message));
  }
  const Calibration cal = outcome.MakeCalibration(true);
  if (!o.quiet) {
    if (!o.no_diagnose) std::cout << "\n" << FormatDiagnosis(outcome.diagnosis);
    if (const std::string note = GravityAmbiguityNote(gravity, outcome.diagnosis.adopted_names());
        !note.empty())
      std::cout << "\ngravity: " << note << "\n";
    std::cout << "\n" << FormatExpandedResults(cal) << FormatFitReport(cal, summary);
  }
  if (!o.output_path.empty()) {
    WriteCalibrationFile(o.output_path, cal);
    if (!o.quiet) std::cout << fmt::format("calibration written to {}\n", o.output_path);
  }
}

}  // namespace

void SetupFitCommand(CLI::App& app) {
  auto opts = std::make_shared<FitCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "fit",
      "Fit the nine calibration parameters (bias, scale, misalignment) to a capture set or to a\n"
      "continuous recording of static poses, print them with their expanded uncertainty U (k = 2: the\n"
      "fit's and the gravity's) and their 1-sigma, and every\n"
      "capture's residual, and write the calibration file. When the residuals exceed what the\n"
      "captures' noise explains, find the effect the model lacks (nonlinearity, cross-axis coupling,\n"
      "temperature, drift, radius offset, speed error, size effect, turntable tilt), add it, and\n"
      "report before and after; when none explains them, say so and what to capture next. A\n"
      "turntable run whose stated radius or speed is implausible or does not match its readings,\n"
      "or a capture that disagrees with all the others, is left out with the reason; a set whose\n"
      "captures disagree beyond that is refused.\n\n"
      "Examples:\n"
      "  accelcal fit captures.csv -o cal.json\n"
      "  accelcal fit --recording imu.txt --gravity 9.81744 -o cal.json\n"
      "  accelcal fit --recording imu.mcap --topic /imu/data -o cal.json\n"
      "  accelcal fit captures.csv --latitude -34.90 --altitude 43 -o cal.json");
  CLI::Option* captures = sub->add_option("captures", opts->captures_path,
                                          "Capture-set file (CSV, format in docs/formats.md)")
                              ->check(InputFile());
  CLI::Option* recording = sub->add_option("--recording", opts->recording_path,
                                           "Continuous recording 't ax ay az [temp_c]' of static poses "
                                           "with a still start, or a ROS bag of them (.bag, .mcap, "
                                           ".db3, a ROS 2 bag folder; --topic); static intervals "
                                           "are found automatically")
                               ->check(InputFileOrBag());
  captures->excludes(recording);
  sub->add_option("-o,--output", opts->output_path, "Write the calibration file (JSON) here");
  opts->gravity.Bind(*sub);
  sub->add_option("--adc-range", opts->adc_range,
                  "ADC output range MIN,MAX in counts (readings at either end count as clipped); "
                  "overrides the file's '# adc_range_counts'")
      ->expected(2)->delimiter(',');
  sub->add_flag("--no-stability-check", opts->no_stability_check,
                "Capture sets: keep static captures that were not still (a bump, drift); by "
                "default they are left out with their reason");
  sub->add_option("--noise-floor", opts->noise_floor,
                  "Capture sets: noise std X,Y,Z in counts for the stability check; by default "
                  "the median over the static captures")
      ->expected(3)->delimiter(',');
  sub->add_option("--min-samples", opts->min_samples, "Shortest usable capture, samples")
      ->capture_default_str();
  sub->add_option("--init-static-s", opts->detector.init_static_s,
                  "Recordings: length of the still start, s (sets the noise level)")
      ->capture_default_str();
  sub->add_option("--threshold-multiplier", opts->detector.threshold_multiplier,
                  "Recordings: a window is static below this many times the still start's variance")
      ->capture_default_str();
  sub->add_option("--window-samples", opts->detector.window_samples,
                  "Recordings: centred variance window, samples (odd)")
      ->capture_default_str();
  opts->format.Bind(*sub, "the recording (--recording)");
  sub->add_flag("--no-diagnose", opts->no_diagnose,
                "Fit the nine-parameter model only: do not look for missing effects");
  sub->add_flag("-q,--quiet", opts->quiet, "Print nothing but errors");
  sub->callback([opts, captures, recording] {
    if (captures->count() == 0 && recording->count() == 0)
      throw CLI::RequiredError("a capture-set file or --recording FILE");
    RunFit(*opts);
  });
}

}  // namespace accelcal::cli
