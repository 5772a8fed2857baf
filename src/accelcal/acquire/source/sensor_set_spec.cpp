#include "accelcal/acquire/source/sensor_set_spec.h"

#include <algorithm>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/base/sensor_columns.h"
#include "accelcal/acquire/mavlink/mavlink_sensor_set.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/source/columns_sensor_set.h"
#include "accelcal/acquire/source/file_link.h"
#include "accelcal/acquire/source/fixture_sim_source.h"
#include "accelcal/acquire/source/linked_sensor_set.h"
#include "accelcal/acquire/source/serial_link.h"
#include "accelcal/acquire/source/source_spec.h"
#include "accelcal/acquire/source/tcp_link.h"

namespace accelcal {
namespace {

constexpr double kClampedPlateDeg = 0.1;  // a fixture plate's placement, per rotation component


void CheckCount(const SensorSetRequest& request, std::size_t have, const std::string& what) {
  if (request.sensors > 0 && static_cast<std::size_t>(request.sensors) != have) {
    throw Error(fmt::format("--sensors {} but {} has {}", request.sensors, what, have));
  }
}

Fixture NumberedFixture(std::size_t n) {
  Fixture f;
  for (std::size_t i = 0; i < n; ++i) {
    FixtureSensor s;
    s.serial = fmt::format("S{:02}", i + 1);
    f.sensors.push_back(s);
  }
  return f;
}

sim::BenchFixture BoardsOf(const Fixture& fixture) {
  sim::BenchFixture bench;
  bench.name = fixture.name;
  bench.placement_u_rad = fixture.placement_u_rad;
  for (const FixtureSensor& s : fixture.sensors) {
    sim::FixtureBoard b;
    b.declared = s;
    b.declared.source.clear();
    b.mounted_to_plate = s.sensor_to_plate;
    bench.boards.push_back(b);
  }
  return bench;
}

std::unique_ptr<SensorSetSource> OpenSimSet(const SourceOptions& options,
                                            const SensorSetRequest& request) {
  sim::Scenario scenario = options.scenario ? *options.scenario : sim::DefaultScenario();
  if (options.seed) scenario.bench.seed = *options.seed;
  if (!scenario.fixture) {
    if (request.fixture) scenario.fixture = BoardsOf(*request.fixture);
    else scenario.fixture = sim::RowOfBoards(request.sensors > 0 ? request.sensors : 1);
    // A plate is set in a jig, not by hand: placed square to within the clamped plate's 0.1 deg
    // (docs/fixtures.md), where the default bench's 0.5 deg is a hand-held sensor's. A board
    // away from the reference point takes the turntable mounting's turn about the spin axis as
    // its own radius error (o theta); a bench's own [fixture] keeps its scenario's figure.
    scenario.bench.placement_error_deg = std::min(scenario.bench.placement_error_deg, kClampedPlateDeg);
  } else if (request.fixture) {
    throw Error("the scenario has its own [fixture]; --fixture is for a bench without one");
  }
  CheckCount(request, scenario.fixture->boards.size(), "the scenario's fixture");
  return std::make_unique<FixtureSimSource>(std::move(scenario), options.sim,
                                            options.dead_after_s, options.gap_factor);
}

std::unique_ptr<ByteLink> TextLink(const SourceSpec& s, const SourceOptions& options) {
  switch (s.kind) {
    case SourceKind::kStdin: return MakeStdinLink(options.stdin_fd);
    case SourceKind::kFile: return OpenFileLink(s.path);
    case SourceKind::kSerial: return MakeSerialLink(s.path, s.baud);
    case SourceKind::kTcp: return MakeTcpLink(s.host, s.port);
    default: return nullptr;
  }
}

bool HasOwnSources(const Fixture& fixture) {
  for (const FixtureSensor& s : fixture.sensors)
    if (!s.source.empty()) return true;
  return false;
}

std::unique_ptr<SensorSetSource> OpenLinked(const Fixture& fixture, const SourceOptions& options) {
  std::vector<std::unique_ptr<SampleSource>> sources;
  for (const FixtureSensor& s : fixture.sensors) {
    if (s.source.empty()) {
      throw Error(fmt::format("fixture: sensor '{}' names no source while others do: give each "
                              "its own, or none (one shared link)", s.serial));
    }
    sources.push_back(OpenSource(s.source, options));
  }
  return std::make_unique<LinkedSensorSet>(fixture, std::move(sources));
}

}  // namespace

std::unique_ptr<SensorSetSource> OpenSensorSet(const std::string& spec,
                                               const SourceOptions& options,
                                               const SensorSetRequest& request) {
  if (std::string why = options.Validate(); !why.empty()) throw Error("source options: " + why);
  if (request.fixture) {
    if (std::string why = request.fixture->Validate(); !why.empty()) throw Error("fixture: " + why);
    CheckCount(request, request.fixture->sensors.size(), "the fixture");
    if (HasOwnSources(*request.fixture)) return OpenLinked(*request.fixture, options);
  }
  const SourceSpec s = ParseSourceSpec(spec);
  if (s.kind == SourceKind::kSim) return OpenSimSet(options, request);
  if (s.kind == SourceKind::kMavlink) {
    // One vehicle, its IMU instances in order: sensor i is IMU i.
    const std::size_t n = request.fixture ? request.fixture->sensors.size()
                                          : static_cast<std::size_t>(std::max(1, request.sensors));
    if (n > 1) {
      if (!request.columns.empty()) throw Error(fmt::format("--columns is for a text line, not '{}'", spec));
      return std::make_unique<MavlinkSensorSet>(spec, request.fixture ? *request.fixture : NumberedFixture(n),
                                                options);
    }
  }
  std::unique_ptr<ByteLink> link = TextLink(s, options);
  if (link == nullptr || request.columns.empty()) {
    const std::size_t n = request.fixture ? request.fixture->sensors.size()
                                          : static_cast<std::size_t>(std::max(1, request.sensors));
    if (n == 1) {
      std::vector<std::unique_ptr<SampleSource>> one;
      one.push_back(OpenSource(spec, options));
      return std::make_unique<LinkedSensorSet>(request.fixture ? *request.fixture
                                                               : NumberedFixture(1),
                                               std::move(one));
    }
    throw Error(fmt::format("{} sensors on '{}': name each sensor's columns with --columns "
                            "(t,ax,ay,az,ax,ay,az,...), or give each its own source in the "
                            "fixture file", n, spec));
  }
  std::string error;
  const std::vector<std::vector<NamedColumn>> columns = SplitSensorColumns(request.columns, &error);
  if (columns.empty()) throw Error(error);
  CheckCount(request, columns.size(), "--columns");
  Fixture fixture = request.fixture ? *request.fixture : NumberedFixture(columns.size());
  if (fixture.sensors.size() != columns.size()) {
    throw Error(fmt::format("--columns names {} sensors, the fixture has {}", columns.size(),
                            fixture.sensors.size()));
  }
  return std::make_unique<ColumnsSensorSet>(std::move(link), std::move(fixture), columns, options);
}

}  // namespace accelcal
