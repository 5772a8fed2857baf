// The virtual bench's fixture (issue 31): several boards on one plate, each with its own truth
// and its own faults, placed and mounted together. The plate is what the wizard places (the
// one-sensor bench's "sensor"); each board feels the plate's specific force at its own offset
// (so its own turntable radius), in its own axes (its mounting), through its own model.
//
// Faults a production fixture has:
//   dead     the board's link falls silent (from dead_from_s on the session clock): no samples.
//   loose    the board is not held firmly: at each placement it settles at a random tilt on the
//            plate (loose_deg, each component) and keeps moving while the plate is handled.
//   mounted  a board put in the fixture other than the fixture file says (mounted_to_plate
//            differs from declared.sensor_to_plate): its orientation check fails for every pose
//            the mistake changes.
// A board that the fixture file says is turned, and is, is no fault: the wizard asks it for
// the plate's pose in its own axes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/fixture.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal::sim {

enum class BoardFault { kNone, kDead, kLoose };

struct FixtureBoard {
  FixtureSensor declared;  // as the fixture file says: serial, rotation, offset
  // As really mounted: sensor -> plate; a signed permutation, det +1 (= declared's unless a
  // board was put in wrong).
  Eigen::Matrix3d mounted_to_plate = Eigen::Matrix3d::Identity();
  std::optional<SensorModel> model;  // its truth; absent: drawn around [sensor]'s (FixtureTruths)
  BoardFault fault = BoardFault::kNone;
  double dead_from_s = 0.0;  // dead: silent from this session time on, s
  double loose_deg = 3.0;    // loose: std of each component of its tilt on the plate, deg
  // loose: how long it rocks on after each placement (e-folding time), s: a board that rocks
  // longer than the plate takes to settle is left out of the pose and retried alone.
  double loose_rock_s = 3.0;
};

// [fixture] of a scenario.
struct BenchFixture {
  std::string name;  // the plate's, as a fixture file's
  std::vector<FixtureBoard> boards;
  // The plate's placement uncertainty as a fixture file states it (Fixture::placement_u_rad),
  // rad; NaN: not stated (the fixture source then states its bench's placement_error_deg: the
  // lab knows how square its jig sets the plate).
  double placement_u_rad = kNaN;
  // A truth drawn for a board without its own: [sensor]'s, each bias moved by up to
  // +-bias_spread_counts, each scale by up to +-scale_spread (relative), each misalignment
  // angle by up to +-misalignment_spread_rad (uniform).
  double bias_spread_counts = 20.0;
  double scale_spread = 0.02;
  double misalignment_spread_rad = 0.005;

  // The fixture as its file says (what the wizard is given).
  Fixture Declared() const;
  // Empty when it can be simulated; otherwise the first problem found, naming the board.
  std::string Validate() const;
};

// Each board's truth: its own when given, else drawn around `base` from `seed`; board i's draw
// depends only on the seed and i (adding a board leaves the others' truths as they were).
std::vector<SensorModel> FixtureTruths(const BenchFixture& fixture, const SensorModel& base,
                                       std::uint64_t seed);

// What `--sensors N` makes: N healthy boards square to the plate, in a row 30 mm apart along
// its x, board (N + 1) / 2 (integer division) at its reference point (centred for odd N; one
// pitch further on +x for even N), serials SIM01, SIM02, ... Throws accelcal::Error for
// n < 1 or n > 64.
BenchFixture RowOfBoards(int n);

}  // namespace accelcal::sim
