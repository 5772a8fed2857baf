// Opening a SensorSetSource (issue 31): a `--source` spec, and how many sensors it carries.
//
//   sim + a scenario with [fixture]   the fixture bench (fixture_sim_source.h), its boards
//   sim + sensors N (--sensors)       a row of N healthy boards (sim::RowOfBoards)
//   sim + a fixture file              its sensors as boards, healthy, mounted as it says
//   file, -, serial, tcp + columns    one line of 3N columns (--columns t,ax,ay,az,ax,ay,az...)
//   a fixture whose sensors each name their own source   one link per sensor
//
// Serials come from the fixture when given (its sensors without their own source are the shared
// link's, in order), else S01, S02, ... (SIM01 ... on the simulator).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "accelcal/base/fixture.h"
#include "accelcal/acquire/source/sensor_set_source.h"
#include "accelcal/acquire/source/source_options.h"

namespace accelcal {

struct SensorSetRequest {
  int sensors = 0;                 // --sensors N; 0: as the fixture, the columns or the scenario
  std::optional<Fixture> fixture;  // --fixture FILE (io/fixture_file.h)
  std::string columns;             // --columns of a line carrying several sensors; may be empty
};

// Throws accelcal::Error naming the disagreement (--sensors 8 with a fixture of 6, columns for
// 3 sensors with --sensors 2, a text link without --columns for more than one sensor, ...).
std::unique_ptr<SensorSetSource> OpenSensorSet(const std::string& spec,
                                               const SourceOptions& options,
                                               const SensorSetRequest& request);

}  // namespace accelcal
