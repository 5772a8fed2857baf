// `accelcal export-cal`: a calibration (file or session) written in another tool's format: a C
// header for firmware, ArduPilot or PX4 parameters, Kalibr's imu.yaml, CSV. Says what the
// target cannot hold (src/accelcal/export/).
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <utility>

#include <fmt/core.h>

#include "accelcal/app/calibration_input.h"
#include "accelcal/base/error.h"
#include "accelcal/io/export/ardupilot_params.h"
#include "accelcal/io/export/c_header.h"
#include "accelcal/io/export/calibration_csv.h"
#include "accelcal/io/export/kalibr_imu_yaml.h"
#include "accelcal/io/export/px4_params.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/io/text_file.h"
#include "accelcal/session/procedure.h"
#include "cli/cli_checks.h"
#include "cli/commands.h"
#include "cli/output.h"
#include "cli/vehicle_writeback_cli.h"
#include "cli/shipped_files.h"

namespace accelcal::cli {
namespace {

struct ExportCalCommandOptions {
  std::string input;        // calibration file (JSON) or session (.db)
  std::string target;       // c-header | ardupilot | px4 | kalibr | csv
  std::string output_path;  // empty: standard output
  std::string device;       // origin, for the file's comment (a session fills both)
  std::string date_utc;
  // ArduPilot / PX4: the driver's scaling (one value for all axes, or x y z).
  std::vector<double> nominal_scale_counts_per_mps2;
  std::vector<double> nominal_bias_counts;
  std::string procedure_path;  // its [sensor] gives both
  std::optional<std::int64_t> px4_device_id;
  // Kalibr.
  std::string allan_path;
  double noise_density = kNaN;  // m/s^2/sqrt(Hz)
  double random_walk = kNaN;    // m/s^3/sqrt(Hz)
  double rate_hz = kNaN;
  double gyro_noise_density = kNaN;
  double gyro_random_walk = kNaN;
  std::string rostopic = "/imu0";
  bool apply = false;  // mavlink:LINK: send the PARAM_SETs (else only say them)
  int sensor = 1;      // --sensor N of a several-sensor session (1-based)
};

// The calibration (app/calibration_input.h: a file or a session), and what is known of its
// origin: what the options say, else the session's device and creation date.
Calibration ReadInput(const ExportCalCommandOptions& o, ExportContext* context) {
  CalibrationInput in = ReadCalibrationInput(o.input, o.sensor - 1);
  context->source = o.input;
  context->device = o.device;
  context->date_utc = o.date_utc;
  if (in.session) {
    if (context->device.empty()) context->device = in.session->device;
    if (context->date_utc.empty()) context->date_utc = in.session->created_utc;
  }
  return std::move(in.calibration);
}

Eigen::Vector3d PerAxis(const std::vector<double>& values, const char* option) {
  if (values.size() == 1) return Eigen::Vector3d::Constant(values[0]);
  if (values.size() == 3) return Eigen::Vector3d(values[0], values[1], values[2]);
  throw Error(fmt::format("{} takes one value (all axes) or three (x y z)", option));
}

DriverScaleOptions DriverScale(const ExportCalCommandOptions& o) {
  DriverScaleOptions d;
  if (!o.procedure_path.empty()) {
    const Procedure procedure = LoadProcedure(o.procedure_path);
    d.nominal_scale_counts_per_mps2 = procedure.nominal.scale_counts_per_mps2;
    d.nominal_bias_counts = procedure.nominal.bias_counts;
  }
  if (!o.nominal_scale_counts_per_mps2.empty())
    d.nominal_scale_counts_per_mps2 = PerAxis(o.nominal_scale_counts_per_mps2, "--nominal-scale-counts-per-mps2");
  if (!o.nominal_bias_counts.empty()) d.nominal_bias_counts = PerAxis(o.nominal_bias_counts, "--nominal-bias-counts");
  if (std::isnan(d.nominal_scale_counts_per_mps2.x()))
    throw Error("this target needs the sensor's nominal scale (the datasheet's counts per m/s^2, "
                "which the flight stack's driver divides by): give --nominal-scale-counts-per-mps2 "
                "(and --nominal-bias-counts for a zero-g level the driver subtracts) or --procedure FILE");
  return d;
}

ExportResult Kalibr(const ExportCalCommandOptions& o, const Calibration& cal, const ExportContext& context) {
  KalibrImuYamlOptions k;
  std::string figures = "given on the command line";
  if (!o.allan_path.empty()) {
    const AllanNoiseFigures f = AllanNoiseForKalibrText(ReadTextFile(o.allan_path), cal, o.allan_path);
    k.accelerometer_noise_density = f.noise_density_mps2_per_sqrt_hz;
    k.accelerometer_random_walk = f.random_walk_mps3_per_sqrt_hz;
    k.update_rate_hz = f.rate_hz;
    figures = fmt::format("from the Allan analysis {}, worst axis (noise density: {}, random walk: {})",
                          o.allan_path, f.noise_density_axis, f.random_walk_axis);
  }
  if (!std::isnan(o.noise_density)) k.accelerometer_noise_density = o.noise_density;
  if (!std::isnan(o.random_walk)) k.accelerometer_random_walk = o.random_walk;
  if (!std::isnan(o.rate_hz)) k.update_rate_hz = o.rate_hz;
  if (std::isnan(k.accelerometer_noise_density) || std::isnan(k.accelerometer_random_walk))
    throw Error("kalibr needs the accelerometer's noise density and random walk: give --allan "
                "allan.json (from `accelcal allan`) or --noise-density and --random-walk");
  if (std::isnan(k.update_rate_hz))
    throw Error("kalibr needs the IMU's update rate: give --rate-hz (or an Allan file with rate_hz)");
  k.gyroscope_noise_density = o.gyro_noise_density;
  k.gyroscope_random_walk = o.gyro_random_walk;
  k.rostopic = o.rostopic;
  k.comment = fmt::format("Kalibr IMU noise model by accelcal export-cal: {}.\nNoise figures {}.",
                          DescribeOrigin(cal, context), figures);
  return WriteKalibrImuYaml(k);
}

ExportResult Export(const ExportCalCommandOptions& o, const Calibration& cal, const ExportContext& context) {
  if (o.target == "c-header") return ExportCHeader(cal, context);
  if (o.target == "ardupilot") return ExportArduPilotParams(cal, DriverScale(o), context);
  if (o.target == "px4") return ExportPx4Params(cal, {DriverScale(o), o.px4_device_id}, context);
  if (o.target == "kalibr") return Kalibr(o, cal, context);
  return ExportCalibrationCsv(cal);
}

void RunExportCal(const ExportCalCommandOptions& o) {
  ExportContext context;
  const Calibration cal = ReadInput(o, &context);
  if (o.target.rfind("mavlink:", 0) == 0) {
    const bool scaling_given = !o.procedure_path.empty() || !o.nominal_scale_counts_per_mps2.empty();
    WriteBackToVehicle(cal, o.target, scaling_given ? std::optional(DriverScale(o)) : std::nullopt, o.apply);
    return;
  }
  if (o.apply) throw Error("--apply writes to a vehicle: it goes with --to mavlink:LINK");
  const ExportResult r = Export(o, cal, context);
  // The statements go where they do not mix with the exported text.
  std::ostream& say = o.output_path.empty() ? std::cerr : std::cout;
  WriteOutputText(o.output_path, r.text);
  if (!o.output_path.empty()) say << fmt::format("{} export written to {}\n", o.target, o.output_path);
  if (r.cannot_hold.empty())
    say << fmt::format("{} holds the whole calibration\n", o.target);
  for (const std::string& s : r.cannot_hold) say << fmt::format("cannot hold: {}\n", s);
  for (const std::string& s : r.notes) say << fmt::format("note: {}\n", s);
}

}  // namespace

void SetupExportCalCommand(CLI::App& app) {
  auto opts = std::make_shared<ExportCalCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "export-cal",
      "Write a calibration in another tool's format and say what that format cannot hold:\n"
      "  c-header   C99 header: constants and a static inline function raw counts -> m/s^2\n"
      "  ardupilot  INS_ACCOFFS_*, INS_ACCSCAL_* (NAME,VALUE .param file)\n"
      "  px4        CAL_ACC0_*OFF, CAL_ACC0_*SCALE (QGroundControl .params file)\n"
      "  kalibr     Kalibr imu.yaml (noise figures from --allan or --noise-density/--random-walk)\n"
      "  csv        parameters with 1-sigma uncertainties, one row each\n"
      "  mavlink:LINK[,imu=N]  ArduPilot's or PX4's parameters written into the vehicle (dry run\n"
      "             unless --apply)\n"
      "The file goes to -o (the statements to stdout) or to stdout (the statements to stderr).\n\n"
      "Examples:\n"
      "  accelcal export-cal cal.json --to c-header -o accel_cal.h\n"
      "  accelcal export-cal cal.json --to ardupilot --procedure procedures/full_calibration.toml -o accel.param\n"
      "  accelcal export-cal session.db --to px4 --nominal-scale-counts-per-mps2 34.8 --nominal-bias-counts 2048\n"
      "  accelcal export-cal cal.json --to kalibr --allan allan.json -o imu.yaml\n"
      "  accelcal export-cal session.db --to mavlink:serial:/dev/ttyACM0@115200 --apply");
  // No CLI11 existence check: a missing file is a failed job (exit 1) with the reader's message.
  sub->add_option("calibration", opts->input, "Calibration file (JSON) or session file (.db)")->required();
  sub->add_option("--to", opts->target, "Target format")
      ->required()
      ->check([] {
        // The file formats by name (their message when none matches), or a vehicle's link.
        CLI::Validator formats = CLI::IsMember({"c-header", "ardupilot", "px4", "kalibr", "csv"});
        return CLI::Validator(
            [formats](std::string& v) mutable { return v.rfind("mavlink:", 0) == 0 ? std::string() : formats(v); },
            formats.get_description());
      }());
  sub->add_flag("--apply", opts->apply,
                "mavlink:LINK: send the PARAM_SETs, wait for each echo and read every value back "
                "(without it: a dry run that prints them)");
  sub->add_option("-o,--output", opts->output_path, "File to write (default: standard output)");
  sub->add_option("--device", opts->device, "Device serial for the file's comment (a session gives it)");
  sub->add_option("--sensor", opts->sensor, "Which sensor of a several-sensor session (1-based)")
      ->check(CLI::PositiveNumber)->capture_default_str();
  sub->add_option("--date", opts->date_utc, "Calibration date for the file's comment (a session gives it)");
  sub->add_option("--nominal-scale-counts-per-mps2", opts->nominal_scale_counts_per_mps2,
                  "ardupilot/px4: the driver's scale, counts per m/s^2 (datasheet; one value or x y z)")
      ->expected(1, 3);
  sub->add_option("--nominal-bias-counts", opts->nominal_bias_counts,
                  "ardupilot/px4: the zero-g level the driver subtracts, counts (default 0; one value or x y z)")
      ->expected(1, 3);
  sub->add_option("--procedure", opts->procedure_path,
                  "ardupilot/px4: take the nominal scale and zero-g level from a procedure's [sensor]")
      ->transform(ShippedFile(kShippedProcedures))
      ->check(InputFile());
  sub->add_option("--px4-device-id", opts->px4_device_id, "px4: CAL_ACC0_ID, the sensor's device id on the autopilot");
  sub->add_option("--allan", opts->allan_path, "kalibr: Allan analysis file (accelcal allan -o)")
      ->check(InputFile());
  sub->add_option("--noise-density", opts->noise_density, "kalibr: accelerometer noise density, m/s^2/sqrt(Hz)");
  sub->add_option("--random-walk", opts->random_walk, "kalibr: accelerometer bias random walk, m/s^3/sqrt(Hz)");
  sub->add_option("--rate-hz", opts->rate_hz, "kalibr: the IMU's update rate, Hz");
  sub->add_option("--gyro-noise-density", opts->gyro_noise_density, "kalibr: gyroscope noise density, rad/s/sqrt(Hz)");
  sub->add_option("--gyro-random-walk", opts->gyro_random_walk, "kalibr: gyroscope random walk, rad/s^2/sqrt(Hz)");
  sub->add_option("--rostopic", opts->rostopic, "kalibr: the IMU's ROS topic")->capture_default_str();
  sub->callback([opts] { RunExportCal(*opts); });
}

}  // namespace accelcal::cli
