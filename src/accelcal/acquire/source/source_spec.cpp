#include "accelcal/acquire/source/source_spec.h"

#include <fmt/format.h>

#include "accelcal/base/text_scan.h"
#include "accelcal/base/error.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/iio/iio_source.h"
#include "accelcal/acquire/mavlink/mavlink_source.h"
#include "accelcal/acquire/source/bag_source.h"
#include "accelcal/acquire/source/file_link.h"
#include "accelcal/acquire/source/host_port.h"
#include "accelcal/bags/bag_open.h"
#include "accelcal/acquire/source/serial_link.h"
#include "accelcal/acquire/source/sim_source.h"
#include "accelcal/acquire/source/stream_source.h"
#include "accelcal/acquire/source/tcp_link.h"

namespace accelcal {
namespace {

constexpr const char* kExpected =
    "expected sim, file:PATH, serial:DEVICE@BAUD, tcp:HOST:PORT, mavlink:LINK, iio:NAME or -";

bool StartsWith(const std::string& text, std::string_view prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

SourceSpec ParseSerial(const std::string& spec) {
  const std::string rest = spec.substr(7);
  const size_t at = rest.rfind('@');
  SourceSpec s{SourceKind::kSerial, rest.substr(0, at), 0, {}, 0};
  if (at == std::string::npos || s.path.empty())
    throw Error(fmt::format("source '{}': expected serial:DEVICE@BAUD, e.g. "
                            "serial:/dev/ttyUSB0@115200", spec));
  if (!detail::ParseLong(rest.substr(at + 1), &s.baud) || s.baud <= 0)
    throw Error(fmt::format("source '{}': baud rate '{}' is not a positive whole number", spec,
                            rest.substr(at + 1)));
  return s;
}

SourceSpec ParseTcp(const std::string& spec) {
  const HostPort hp = ParseHostPort(spec.substr(4), spec, "tcp:HOST:PORT, e.g. tcp:192.168.7.2:5000");
  return {SourceKind::kTcp, {}, 0, hp.host, hp.port};
}

std::unique_ptr<SampleSource> OpenSim(const SourceOptions& options) {
  sim::Scenario scenario = options.scenario ? *options.scenario : sim::DefaultScenario();
  if (options.seed) scenario.bench.seed = *options.seed;
  return std::make_unique<SimSource>(std::move(scenario), options.sim, options.dead_after_s,
                                     options.gap_factor);
}

}  // namespace

SourceSpec ParseSourceSpec(const std::string& spec) {
  if (spec == "sim") return {};
  if (spec == "-") return {SourceKind::kStdin, {}, 0, {}, 0};
  if (StartsWith(spec, "file:")) {
    if (spec.size() == 5) throw Error("source 'file:': expected file:PATH, e.g. file:rec.txt");
    return {SourceKind::kFile, spec.substr(5), 0, {}, 0};
  }
  if (StartsWith(spec, "serial:")) return ParseSerial(spec);
  if (StartsWith(spec, "tcp:")) return ParseTcp(spec);
  if (StartsWith(spec, "mavlink:")) {
    ParseMavlinkSpec(spec);  // throws for a malformed one
    return {SourceKind::kMavlink, spec, 0, {}, 0};
  }
  if (StartsWith(spec, "iio:")) {
    ParseIioSpec(spec);
    return {SourceKind::kIio, spec, 0, {}, 0};
  }
  throw Error(fmt::format("unknown source '{}': {}", detail::TrimBlanks(spec), kExpected));
}

std::unique_ptr<SampleSource> OpenSource(const std::string& spec, const SourceOptions& options) {
  if (std::string why = options.Validate(); !why.empty())
    throw Error("source options: " + why);
  const SourceSpec s = ParseSourceSpec(spec);
  using Pacing = StreamSource::Pacing;
  switch (s.kind) {
    case SourceKind::kSim:
      return OpenSim(options);
    case SourceKind::kStdin:
      return std::make_unique<StreamSource>(MakeStdinLink(options.stdin_fd), options,
                                            Pacing::kAsFastAsPossible);
    case SourceKind::kFile:
      if (bags::DetectBag(s.path)) return std::make_unique<BagSource>(s.path, options);  // a ROS bag
      return std::make_unique<StreamSource>(
          OpenFileLink(s.path), options,
          options.realtime ? Pacing::kByT : Pacing::kAsFastAsPossible);
    case SourceKind::kSerial:
      return std::make_unique<StreamSource>(MakeSerialLink(s.path, s.baud), options,
                                            Pacing::kAsFastAsPossible);
    case SourceKind::kTcp:
      return std::make_unique<StreamSource>(MakeTcpLink(s.host, s.port), options,
                                            Pacing::kAsFastAsPossible);
    case SourceKind::kMavlink:
      return std::make_unique<MavlinkSource>(ParseMavlinkSpec(spec), options);
    case SourceKind::kIio:
      return OpenIioSource(ParseIioSpec(spec), options);
  }
  throw Error("unreachable source kind");
}

}  // namespace accelcal
