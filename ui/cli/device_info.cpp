// `accelcal device-info --source SPEC`: what a live device is before a session uses it. For a
// MAVLink vehicle: who answers, the IMU messages it streams (listened to for --listen s), the
// rate request's outcome, the resolution, and its own accelerometer calibration with what
// accelcal does about it (undone in wizard and record, or why it cannot be); --reset [--apply]
// asks it to forget that calibration. For an IIO device: channels, scan types, scale and offset
// (stated, not applied), sampling frequency, trigger, buffer, and the rate a short read reached.
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include "accelcal/acquire/iio/iio_source.h"
#include "accelcal/acquire/mavlink/mavlink_source.h"
#include "accelcal/acquire/source/source_spec.h"
#include "accelcal/acquire/source/wall_clock.h"
#include "accelcal/app/device/vehicle_writeback.h"
#include "accelcal/base/error.h"
#include "cli/cli_checks.h"
#include "cli/commands.h"

namespace accelcal::cli {
namespace {

struct DeviceInfoOptions {
  std::string source;
  double listen_s = 3.0;
  bool reset = false;
  bool apply = false;
};

// Reads the source for listen_s (the samples are only counted).
long Listen(SampleSource& source, double listen_s) {
  std::vector<Sample> samples;
  long count = 0;
  const double end_s = source_detail::WallNowS() + listen_s;
  while (source_detail::WallNowS() < end_s) {
    samples.clear();
    source.Read(std::min(0.2, end_s - source_detail::WallNowS()), &samples);
    count += static_cast<long>(samples.size());
  }
  return count;
}

void Say(const std::string& line) { std::cout << line << "\n"; }

void DescribeSourceState(SampleSource& source, long samples, double listen_s) {
  Say(fmt::format("listened {:g} s: {} samples; {}", listen_s, samples, source.status().BriefReport()));
  Say("reading: " + source.DescribeReading());
  if (const std::string note = source.status().ResolutionNote(); !note.empty()) Say("resolution: " + note);
  if (!source.status().last_notice.empty()) Say("latest notice: " + source.status().last_notice);
  if (!source.status().last_malformed.empty()) Say("latest bad input: " + source.status().last_malformed);
}

void MavlinkInfo(const DeviceInfoOptions& o) {
  MavlinkSource source(ParseMavlinkSpec(o.source), SourceOptions{});
  const long samples = Listen(source, o.listen_s);
  Say(fmt::format("vehicle: {} on {}", source.connection().vehicle().Describe(), source.connection().LinkName()));
  for (const auto& [key, frames] : source.imu_streams())
    Say(fmt::format("stream: {} of IMU {}: {} frames ({:.1f} per s)", mavlink::MessageName(key.first), key.second,
                    frames, frames / o.listen_s));
  DescribeSourceState(source, samples, o.listen_s);
  const VehicleAccelParams params = ReadVehicleAccelParams(source.connection(), source.spec().imu);
  for (const std::string& line : DescribeVehicleAccelParams(params)) Say(line);
  std::string why;
  if (UndoOf(params, &why))
    Say("accelcal wizard and record take this calibration back out of every sample (the sensor's own "
        "response); --vehicle-calibration as-is leaves it in");
  else
    Say("it cannot be undone: " + why + "; reset it (--reset --apply) before a calibration");
  if (!o.reset) return;
  const std::vector<ParamWrite> writes = ResetWrites(params);
  Say("reset: the vehicle's calibration of this IMU set to offsets 0 and scales 1:");
  for (const std::string& line : DescribeWrites(writes)) Say(line);
  if (!o.apply) {
    Say("dry run: nothing was sent (--apply sends them)");
    return;
  }
  const WritebackOutcome outcome = ApplyWrites(source.connection(), params.stack, writes);
  for (const std::string& line : outcome.Lines()) Say(line);
  if (!outcome.ok()) throw Error("the reset stopped: " + (outcome.failed.empty() ? outcome.reread_mismatches.front() : outcome.failed));
}

void IioInfo(const DeviceInfoOptions& o) {
  IioSource source(ParseIioSpec(o.source), SourceOptions{});
  for (const std::string& line : DescribeIioDevice(source.device())) Say(line);
  const long samples = Listen(source, o.listen_s);
  DescribeSourceState(source, samples, o.listen_s);
}

void RunDeviceInfo(const DeviceInfoOptions& o) {
  const SourceSpec spec = ParseSourceSpec(o.source);
  if ((o.reset || o.apply) && spec.kind != SourceKind::kMavlink)
    throw Error("--reset and --apply are for a MAVLink vehicle's calibration");
  if (spec.kind == SourceKind::kMavlink) return MavlinkInfo(o);
  if (spec.kind == SourceKind::kIio) return IioInfo(o);
  throw Error(fmt::format("device-info describes mavlink: and iio: sources; '{}' is neither", o.source));
}

}  // namespace

void SetupDeviceInfoCommand(CLI::App& app) {
  auto opts = std::make_shared<DeviceInfoOptions>();
  CLI::App* sub = app.add_subcommand(
      "device-info",
      "What a live device is, before a session uses it: a MAVLink vehicle (who answers, the IMU\n"
      "messages it streams and at what rate, the resolution, its own accelerometer calibration\n"
      "and whether accelcal can take it back out) or a Linux IIO device (channels, scan types,\n"
      "scale and offset, sampling frequency, trigger, the rate reached).");
  sub->footer(
      "Examples:\n"
      "  accelcal device-info --source mavlink:serial:/dev/ttyACM0@115200\n"
      "  accelcal device-info --source mavlink:udp:0.0.0.0:14550,imu=1 --reset --apply\n"
      "  accelcal device-info --source iio:adxl345");
  sub->add_option("--source", opts->source, "mavlink:LINK[,imu=N,...] or iio:DEVICE[,...]")->required();
  sub->add_option("--listen", opts->listen_s, "Seconds to read the stream before describing it")
      ->check(CLI::Range(0.5, 600.0))->capture_default_str();
  sub->add_flag("--reset", opts->reset,
                "MAVLink: set the IMU's calibration on the vehicle to offsets 0 and scales 1 (dry run "
                "unless --apply)");
  sub->add_flag("--apply", opts->apply, "MAVLink --reset: send the PARAM_SETs");
  sub->callback([opts] { RunDeviceInfo(*opts); });
}

}  // namespace accelcal::cli
