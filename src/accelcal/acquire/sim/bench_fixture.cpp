#include "accelcal/acquire/sim/bench_fixture.h"

#include <cmath>
#include <random>

#include <Eigen/LU>
#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal::sim {
namespace {

constexpr double kRowPitchM = 0.030;  // boards of a row of --sensors N, m apart
constexpr int kMaxBoards = 64;

// A stream of its own for board i, so that its draw does not depend on the other boards.
std::mt19937_64 BoardStream(std::uint64_t seed, std::size_t board) {
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(board), 0x31u};
  return std::mt19937_64(seq);
}

SensorModel DrawAround(const SensorModel& base, const BenchFixture& f, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  SensorModel m = base;
  for (int i = 0; i < 3; ++i) m.bias_counts(i) += f.bias_spread_counts * unit(rng);
  for (int i = 0; i < 3; ++i) m.scale_counts_per_mps2(i) *= 1.0 + f.scale_spread * unit(rng);
  m.a_yz_rad += f.misalignment_spread_rad * unit(rng);
  m.a_zy_rad += f.misalignment_spread_rad * unit(rng);
  m.a_zx_rad += f.misalignment_spread_rad * unit(rng);
  return m;
}

}  // namespace

Fixture BenchFixture::Declared() const {
  Fixture f;
  f.name = name;
  f.placement_u_rad = placement_u_rad;
  for (const FixtureBoard& b : boards) f.sensors.push_back(b.declared);
  return f;
}

std::string BenchFixture::Validate() const {
  if (boards.size() > static_cast<std::size_t>(kMaxBoards)) {
    return fmt::format("fixture: {} boards, at most {}", boards.size(), kMaxBoards);
  }
  if (std::string why = Declared().Validate(); !why.empty()) return "fixture: " + why;
  if (!(bias_spread_counts >= 0.0) || !(scale_spread >= 0.0) || !(scale_spread < 0.5) ||
      !(misalignment_spread_rad >= 0.0) || !(misalignment_spread_rad < 0.1)) {
    return "fixture: the spreads must not be negative (scale_spread < 0.5, "
           "misalignment_spread_rad < 0.1)";
  }
  for (std::size_t i = 0; i < boards.size(); ++i) {
    const FixtureBoard& b = boards[i];
    const std::string where = fmt::format("fixture: board {} ('{}')", i + 1, b.declared.serial);
    FixtureSensor mounted = b.declared;
    mounted.sensor_to_plate = b.mounted_to_plate;
    Fixture probe;
    probe.sensors.push_back(mounted);
    if (!probe.Validate().empty()) return where + ": its mounting is not a right-angle turn";
    if (b.model) {
      if (std::string why = b.model->Validate(); !why.empty()) return where + ": " + why;
    }
    if (!(b.dead_from_s >= 0.0) || !std::isfinite(b.dead_from_s)) {
      return where + ": dead_from_s must not be negative";
    }
    if (!(b.loose_deg > 0.0) || !(b.loose_deg <= 45.0)) {
      return where + ": loose_deg must be in (0, 45]";
    }
  }
  return {};
}

std::vector<SensorModel> FixtureTruths(const BenchFixture& fixture, const SensorModel& base,
                                       std::uint64_t seed) {
  std::vector<SensorModel> truths;
  for (std::size_t i = 0; i < fixture.boards.size(); ++i) {
    const FixtureBoard& b = fixture.boards[i];
    if (b.model) {
      truths.push_back(*b.model);
      continue;
    }
    std::mt19937_64 rng = BoardStream(seed, i);
    truths.push_back(DrawAround(base, fixture, rng));
  }
  return truths;
}

BenchFixture RowOfBoards(int n) {
  if (n < 1 || n > kMaxBoards) {
    throw Error(fmt::format("--sensors must be 1..{}, got {}", kMaxBoards, n));
  }
  BenchFixture f;
  for (int i = 0; i < n; ++i) {
    FixtureBoard b;
    b.declared.serial = fmt::format("SIM{:02}", i + 1);
    // Board (n + 1) / 2 at the reference point (the one whose turntable radius is the
    // procedure's: the wizard's lead), the others either side.
    b.declared.offset_m = Eigen::Vector3d((i - (n - 1) / 2) * kRowPitchM, 0.0, 0.0);
    f.boards.push_back(b);
  }
  return f;
}

}  // namespace accelcal::sim
