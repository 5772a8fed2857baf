#include "accelcal/acquire/source/fixture_sim_source.h"

#include <cmath>

#include <Eigen/Geometry>
#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/acquire/source/wall_clock.h"

namespace accelcal {
namespace {

constexpr double kBoardDegToRad = M_PI / 180.0;
// A loose board rocks on after each placement (for its loose_rock_s, e-folding) at
// kLooseRockHz with a quarter of its loose_deg: clearly motion to a stillness check, then quiet.
constexpr double kLooseRockHz = 4.0;

// Board i's streams: from the seed and i alone.
std::uint64_t BoardSeed(std::uint64_t seed, std::size_t board) {
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(board), 0x5eu};
  std::uint64_t out[1];
  std::uint32_t words[2];
  seq.generate(words, words + 2);
  out[0] = (static_cast<std::uint64_t>(words[0]) << 32) | words[1];
  return out[0];
}

sim::Scenario PlateScenario(sim::Scenario scenario) {
  scenario.fixture.reset();
  return scenario;
}

sim::Scenario BoardScenario(const sim::Scenario& plate, const SensorModel& truth,
                            std::size_t board) {
  sim::Scenario s = PlateScenario(plate);
  s.sensor.model = truth;
  s.bench.seed = BoardSeed(plate.bench.seed, board);
  return s;
}

}  // namespace

struct FixtureSimSource::Board {
  Board(const sim::FixtureBoard& spec_in, sim::Scenario scenario, double gap_factor,
        double dead_after_s)
      : spec(spec_in),
        bench(std::move(scenario)),
        tracker(gap_factor, dead_after_s, source_detail::WallNowS()),
        loose_rng(bench.scenario().bench.seed ^ 0x10053ULL) {}

  sim::FixtureBoard spec;
  sim::VirtualBench bench;  // its truth and its noise
  StatusTracker tracker;
  std::mt19937_64 loose_rng;
  Eigen::Matrix3d tilt = Eigen::Matrix3d::Identity();  // loose: on the plate, this placement
  double rock_phase_rad = 0.0;  // loose: its rocking's phase, this placement
  std::vector<Sample> pending;  // measured during the plate's Read, not yet delivered
  bool ended = false;
};

FixtureSimSource::FixtureSimSource(sim::Scenario scenario, const SimOptions& options,
                                   double dead_after_s, double gap_factor) {
  if (!scenario.fixture) throw Error("sim: the scenario has no [fixture] of boards");
  if (std::string why = scenario.Validate(); !why.empty()) throw Error(why);
  bench_fixture_ = *scenario.fixture;
  declared_ = bench_fixture_.Declared();
  if (std::isnan(declared_.placement_u_rad))
    declared_.placement_u_rad = scenario.bench.placement_error_deg * M_PI / 180.0;
  const std::vector<SensorModel> truths =
      sim::FixtureTruths(bench_fixture_, scenario.sensor.model, scenario.bench.seed);
  plate_ = std::make_unique<SimSource>(PlateScenario(scenario), options, dead_after_s, gap_factor);
  for (std::size_t i = 0; i < bench_fixture_.boards.size(); ++i) {
    boards_.push_back(std::make_unique<Board>(bench_fixture_.boards[i],
                                              BoardScenario(plate_->scenario(), truths[i], i),
                                              gap_factor, dead_after_s));
    ReadResult ignored;
    boards_.back()->tracker.OnLinkUp(source_detail::WallNowS(), &ignored);
  }
  plate_->set_force_tap([this](double t_s, const Eigen::Matrix3d& f) { OnPlateForce(t_s, f); });
}

FixtureSimSource::~FixtureSimSource() = default;

std::string FixtureSimSource::Describe() const {
  return fmt::format("sim ({} boards{})", boards_.size(),
                     declared_.name.empty() ? "" : ", " + declared_.name);
}

const SourceStatus& FixtureSimSource::status(std::size_t sensor) const {
  return boards_.at(sensor)->tracker.status();
}

const SensorModel& FixtureSimSource::truth(std::size_t board) const {
  return boards_.at(board)->bench.scenario().sensor.model;
}

Eigen::Matrix3d FixtureSimSource::mounted_to_plate(std::size_t board) const {
  const Board& b = *boards_.at(board);
  return b.spec.mounted_to_plate * b.tilt;
}

ReadResult FixtureSimSource::Read(double timeout_s, SensorSetSamples* out) {
  out->Resize(boards_.size());
  plate_samples_.clear();
  const ReadResult plate = plate_->Read(timeout_s, &plate_samples_);
  const double wall_s = source_detail::WallNowS();
  ReadResult all;
  bool any_live = false;
  for (std::size_t i = 0; i < boards_.size(); ++i) {
    Board& b = *boards_[i];
    ReadResult one;
    if (!b.pending.empty()) {
      std::vector<Sample>& dest = out->per_sensor[i];
      const std::size_t first = dest.size();
      dest.insert(dest.end(), b.pending.begin(), b.pending.end());
      b.tracker.OnSamples(dest.data() + first, static_cast<long>(b.pending.size()), wall_s, &one);
      b.pending.clear();
    }
    b.tracker.Tick(wall_s, &one);
    if (plate.ended && !b.ended) {
      b.tracker.OnEnded(&one);
      b.ended = true;
    }
    any_live = any_live || !b.ended;
    MergeReadResult(one, &all);
  }
  all.ended = plate.ended && !any_live;
  return all;
}

void FixtureSimSource::OnPlateForce(double t_s, const Eigen::Matrix3d& f_plate_per_axis_mps2) {
  if (plate_->placements() != placements_seen_) {
    placements_seen_ = plate_->placements();
    last_placement_s_ = t_s;
    SettleLooseBoards(t_s);
  }
  for (const std::unique_ptr<Board>& board : boards_) {
    Board& b = *board;
    if (b.spec.fault == sim::BoardFault::kDead && t_s >= b.spec.dead_from_s) continue;
    b.pending.push_back(b.bench.MeasurePerAxis(BoardForce(b, t_s, f_plate_per_axis_mps2), t_s));
  }
}

void FixtureSimSource::SettleLooseBoards(double /*t_s*/) {
  for (const std::unique_ptr<Board>& board : boards_) {
    Board& b = *board;
    if (b.spec.fault != sim::BoardFault::kLoose) continue;
    std::normal_distribution<double> tilt_rad(0.0, b.spec.loose_deg * kBoardDegToRad);
    const Eigen::Vector3d rotation_vector(tilt_rad(b.loose_rng), tilt_rad(b.loose_rng),
                                          tilt_rad(b.loose_rng));
    b.tilt = Eigen::AngleAxisd(rotation_vector.norm(), rotation_vector.norm() > 0.0
                                                           ? rotation_vector.normalized()
                                                           : Eigen::Vector3d::UnitX())
                 .toRotationMatrix();
    b.rock_phase_rad = std::uniform_real_distribution<double>(0.0, 2.0 * M_PI)(b.loose_rng);
  }
}

Eigen::Matrix3d FixtureSimSource::BoardForce(const Board& b, double t_s,
                                             const Eigen::Matrix3d& f_plate) const {
  Eigen::Matrix3d f = f_plate;
  const sim::Mounting& m = plate_->mounting();
  if (m.kind == CaptureKind::kTurntable && b.spec.declared.offset_m.squaredNorm() > 0.0) {
    // The board's sensing point is elsewhere on the turning table: its own centripetal term.
    Eigen::Vector3d offset_table = m.platform_rotation * b.spec.declared.offset_m;
    offset_table.z() = 0.0;
    const Eigen::Vector3d extra_plate = m.platform_rotation.transpose() *
                                        (-m.omega_rad_per_s * m.omega_rad_per_s * offset_table);
    f.colwise() += extra_plate;
  }
  Eigen::Matrix3d board_to_plate = b.spec.mounted_to_plate;
  if (b.spec.fault == sim::BoardFault::kLoose) {
    const double age_s = t_s - last_placement_s_;
    // It rocks about all three of its axes at once (three frequencies), so that gravity moves in
    // it whichever face is up.
    const double amplitude_rad =
        0.25 * b.spec.loose_deg * kBoardDegToRad * std::exp(-age_s / b.spec.loose_rock_s);
    const Eigen::Vector3d phase(0.0, 1.0, 2.0);
    Eigen::Vector3d rock_rad;
    for (int i = 0; i < 3; ++i)
      rock_rad(i) = amplitude_rad * std::sin(2.0 * M_PI * kLooseRockHz * (1.0 + 0.25 * i) * age_s +
                                             phase(i) + b.rock_phase_rad);
    const double angle_rad = rock_rad.norm();
    if (angle_rad > 0.0)
      board_to_plate = board_to_plate * b.tilt * Eigen::AngleAxisd(angle_rad, rock_rad / angle_rad);
    else
      board_to_plate = board_to_plate * b.tilt;
  }
  return board_to_plate.transpose() * f;
}

}  // namespace accelcal
