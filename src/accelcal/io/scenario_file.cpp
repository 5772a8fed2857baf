// ParseScenario / LoadScenario: TOML -> Scenario. Every table refuses keys it does not know.
#include "accelcal/io/scenario_file.h"

#include <fstream>
#include <sstream>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "accelcal/io/detail/fixture_toml.h"
#include "accelcal/io/detail/json_values.h"
#include "accelcal/io/detail/toml_reader.h"
#include "accelcal/base/error.h"
#include "accelcal/acquire/sim/scenario.h"

namespace accelcal::sim {
namespace {

using detail::NumberRange;
using detail::TomlTableReader;

SensorSpec ReadSensor(TomlTableReader& r, const std::string& source) {
  SensorSpec s;
  s.model.bias_counts = r.Vector3("bias_counts", std::nullopt);
  s.model.scale_counts_per_mps2 =
      r.Vector3("scale_counts_per_mps2", std::nullopt, NumberRange::kPositive);
  if (const toml::table* mis = r.Table("misalignment_rad")) {
    TomlTableReader m(*mis, "sensor.misalignment_rad", source);
    s.model.a_yz_rad = m.Number("yz", 0.0);
    s.model.a_zy_rad = m.Number("zy", 0.0);
    s.model.a_zx_rad = m.Number("zx", 0.0);
    m.Finish();
  }
  s.noise_counts = r.Vector3("noise_counts", Eigen::Vector3d::Zero(), NumberRange::kNonNegative);
  s.rate_hz = r.Number("rate_hz", 100.0, NumberRange::kPositive);
  BiasNoiseSpec& bn = s.bias_noise;
  bn.random_walk_counts_per_sqrt_s = r.Vector3("bias_random_walk_counts_per_sqrt_s",
                                               Eigen::Vector3d::Zero(), NumberRange::kNonNegative);
  bn.instability_counts =
      r.Vector3("bias_instability_counts", Eigen::Vector3d::Zero(), NumberRange::kNonNegative);
  bn.instability_tau_min_s =
      r.Number("bias_instability_tau_min_s", bn.instability_tau_min_s, NumberRange::kPositive);
  bn.instability_tau_max_s =
      r.Number("bias_instability_tau_max_s", bn.instability_tau_max_s, NumberRange::kPositive);
  if (!(bn.instability_tau_max_s > bn.instability_tau_min_s)) {
    const char* key = r.Has("bias_instability_tau_max_s") ? "bias_instability_tau_max_s"
                                                           : "bias_instability_tau_min_s";
    r.Fail(*r.Get(key), key, "bias_instability_tau_max_s must exceed bias_instability_tau_min_s");
  }
  return s;
}

AdcSpec ReadAdc(TomlTableReader& r) {
  AdcSpec a;
  const std::int64_t bits = r.Integer("bits", std::nullopt);
  if (bits < 1 || bits > 32) r.Fail(*r.Get("bits"), "bits", "must be between 1 and 32");
  a.bits = static_cast<int>(bits);
  a.is_signed = r.Bool("signed", false);
  return a;
}

BenchSpec ReadBench(TomlTableReader& r) {
  BenchSpec b;
  b.gravity_mps2 = r.Number("gravity_mps2", b.gravity_mps2, NumberRange::kPositive);
  const std::int64_t seed = r.Integer("seed", static_cast<std::int64_t>(b.seed));
  if (seed < 0) r.Fail(*r.Get("seed"), "seed", "must not be negative");
  b.seed = static_cast<std::uint64_t>(seed);
  b.placement_error_deg =
      r.Number("placement_error_deg", b.placement_error_deg, NumberRange::kNonNegative);
  b.gap_s = r.Number("gap_s", b.gap_s, NumberRange::kNonNegative);
  b.capture_duration_s =
      r.Number("capture_duration_s", b.capture_duration_s, NumberRange::kPositive);
  b.temperature_c = r.Number("temperature_c", b.temperature_c);
  b.recording_quiet_start_s =
      r.Number("recording_quiet_start_s", b.recording_quiet_start_s, NumberRange::kNonNegative);
  b.move_s = r.Number("move_s", b.move_s, NumberRange::kPositive);
  b.table_tilt_deg = r.Vector2("table_tilt_deg", b.table_tilt_deg);
  return b;
}

Bump ReadBump(TomlTableReader& r) {
  Bump b;
  b.capture = static_cast<int>(r.Integer("capture", std::nullopt));
  b.at_s = r.Number("at_s", std::nullopt, NumberRange::kNonNegative);
  b.peak_mps2 = r.Number("peak_mps2", std::nullopt);
  b.duration_s = r.Number("duration_s", std::nullopt, NumberRange::kPositive);
  return b;
}

EffectsSpec ReadEffects(TomlTableReader& r, const std::string& source, double ambient_c) {
  EffectsSpec e;
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  e.quadratic_counts_per_mps2_sq = r.Vector3("quadratic_counts_per_mps2_sq", zero);
  e.bias_temp_coeff_counts_per_c = r.Vector3("bias_temp_coeff_counts_per_c", zero);
  e.scale_temp_coeff_per_c = r.Vector3("scale_temp_coeff_per_c", zero);
  if (const toml::table* t = r.Table("temperature")) {
    TomlTableReader tr(*t, "effects.temperature", source);
    e.temperature = TemperatureRamp{tr.Number("start_c", ambient_c), tr.Number("end_c", ambient_c),
                                    tr.Number("warmup_tau_s", 0.0, NumberRange::kNonNegative)};
    tr.Finish();
  }
  e.bias_drift_counts_per_s = r.Vector3("bias_drift_counts_per_s", zero);
  e.radius_offset_m = r.Number("radius_offset_m", 0.0);
  e.rpm_scale = r.Number("rpm_scale", 0.0);
  e.size_effect_m = r.Vector3("size_effect_m", zero);
  e.turntable_tilt_rad = r.Number("turntable_tilt_rad", 0.0);
  e.settling_share = r.Vector3("settling_share", zero);
  e.settling_tau_s = r.Number("settling_tau_s", 15.0);
  if (const toml::array* bumps = r.ArrayOfTables("bump")) {
    for (std::size_t i = 0; i < bumps->size(); ++i) {
      TomlTableReader br(*bumps->get(i)->as_table(), fmt::format("effects.bump {}", i), source);
      e.bumps.push_back(ReadBump(br));
      br.Finish();
    }
  }
  return e;
}

SensorAxis ReadAxis(TomlTableReader& r, std::string_view key) {
  const std::string text = r.String(key, std::nullopt);
  const std::optional<SensorAxis> axis = StringToSensorAxis(text);
  if (!axis) r.Fail(*r.Get(key), key, "expected one of +x -x +y -y +z -z, got '" + text + "'");
  return *axis;
}

std::optional<SensorAxis> OptionalAxis(TomlTableReader& r, std::string_view key) {
  if (!r.Has(key)) return std::nullopt;
  return ReadAxis(r, key);
}

std::optional<Eigen::Vector3d> OptionalDirection(TomlTableReader& r, std::string_view key) {
  if (!r.Has(key)) return std::nullopt;
  const Eigen::Vector3d v = r.Vector3(key, std::nullopt);
  if (!(v.norm() > 0.0)) r.Fail(*r.Get(key), key, "must not be the zero vector");
  return v.normalized();
}

Mistake ReadMistake(TomlTableReader& r) {
  Mistake m;
  m.asked_up = OptionalDirection(r, "asked_up");
  m.asked_radial = OptionalAxis(r, "asked_radial");
  m.asked_up_axis = OptionalAxis(r, "asked_up_axis");
  m.asked_radius_m = r.Number("asked_radius_m", kNaN, NumberRange::kPositive);
  const std::int64_t after = r.Integer("after", 0);
  const std::int64_t times = r.Integer("times", 1);
  if (after < 0 || after > 1000) r.Fail(*r.Get("after"), "after", "must be 0..1000");
  if (times < 1 || times > 1000) r.Fail(*r.Get("times"), "times", "must be 1..1000");
  m.after = static_cast<int>(after);
  m.times = static_cast<int>(times);
  m.up = OptionalDirection(r, "up");
  m.radial = OptionalAxis(r, "radial");
  m.up_axis = OptionalAxis(r, "up_axis");
  m.radius_m = r.Number("radius_m", kNaN, NumberRange::kPositive);
  m.bump_at_s = r.Number("bump_at_s", kNaN, NumberRange::kNonNegative);
  m.bump_peak_mps2 = r.Number("bump_peak_mps2", m.bump_peak_mps2, NumberRange::kPositive);
  m.bump_duration_s = r.Number("bump_duration_s", m.bump_duration_s, NumberRange::kPositive);
  return m;
}

Technician ReadTechnician(TomlTableReader& r, const std::string& source) {
  Technician t;
  t.leveling_gain = r.Number("leveling_gain", t.leveling_gain, NumberRange::kPositive);
  if (const toml::array* shakes = r.ArrayOfTables("shake")) {
    for (std::size_t i = 0; i < shakes->size(); ++i) {
      TomlTableReader sr(*shakes->get(i)->as_table(), fmt::format("technician.shake {}", i), source);
      Shake s;
      s.from_s = sr.Number("from_s", 0.0, NumberRange::kNonNegative);
      s.to_s = sr.Number("to_s", std::nullopt, NumberRange::kPositive);
      s.rms_mps2 = sr.Number("rms_mps2", std::nullopt, NumberRange::kNonNegative);
      sr.Finish();
      t.shakes.push_back(s);
    }
  }
  if (const toml::array* mistakes = r.ArrayOfTables("mistake")) {
    for (std::size_t i = 0; i < mistakes->size(); ++i) {
      TomlTableReader mr(*mistakes->get(i)->as_table(), fmt::format("technician.mistake {}", i), source);
      t.mistakes.push_back(ReadMistake(mr));
      mr.Finish();
    }
  }
  return t;
}

LabSpec ReadLab(TomlTableReader& r) {
  LabSpec lab;
  lab.gravity = r.String("gravity", lab.gravity);
  lab.gravity_sigma_mps2 = r.Number("gravity_sigma_mps2", lab.gravity_sigma_mps2, NumberRange::kPositive);
  lab.equipment = r.String("equipment", lab.equipment);
  for (const char* key : {"gravity", "equipment"})
    if (r.Has(key) && r.String(key, std::nullopt).find_first_of("\r\n") != std::string::npos)
      r.Fail(*r.Get(key), key, "must be a single line (the welcome's answer)");
  return lab;
}

void ReadTurntable(TomlTableReader& r, CapturePlan& c) {
  c.radius_m = r.Number("radius_m", std::nullopt, NumberRange::kNonNegative);
  c.rpm = r.Number("rpm", std::nullopt, NumberRange::kNonNegative);
  c.radial_axis = ReadAxis(r, "radial_axis");
  c.up_axis = ReadAxis(r, "up_axis");
  if (std::abs(SensorAxisVector(c.radial_axis).dot(SensorAxisVector(c.up_axis))) > 0.5) {
    r.Fail(*r.Get("up_axis"), "up_axis", "must be perpendicular to radial_axis");
  }
}

CapturePlan ReadCapture(TomlTableReader& r) {
  CapturePlan c;
  const std::string kind = r.String("kind", std::nullopt);
  const std::optional<CaptureKind> parsed = StringToCaptureKind(kind);
  if (!parsed)
    r.Fail(*r.Get("kind"), "kind", "expected \"static\" or \"turntable\", got '" + kind + "'");
  c.kind = *parsed;
  c.label = r.String("label", std::nullopt);
  if (c.label.find_first_of("\r\n") != std::string::npos) {
    r.Fail(*r.Get("label"), "label", "must be a single line");
  }
  if (r.Has("duration_s"))
    c.duration_s = r.Number("duration_s", std::nullopt, NumberRange::kPositive);
  if (c.kind == CaptureKind::kTurntable) {
    ReadTurntable(r, c);
  } else {
    const Eigen::Vector3d up = r.Vector3("up", std::nullopt);
    if (!(up.norm() > 0.0)) r.Fail(*r.Get("up"), "up", "must not be the zero vector");
    c.up = up.normalized();
  }
  return c;
}

// [[fixture.board]]: the fixture file's fields, and what only the virtual bench has (the truth,
// the real mounting, the faults).
FixtureBoard ReadBoard(TomlTableReader& r, const std::string& source) {
  FixtureBoard b;
  b.declared = detail::ReadFixtureSensorFields(r);
  b.mounted_to_plate = b.declared.sensor_to_plate;
  if (r.Has("mounted_x") || r.Has("mounted_y")) {
    b.mounted_to_plate = detail::ReadSensorToPlate(r, "mounted_x", "mounted_y");
  }
  if (r.Has("bias_counts") || r.Has("scale_counts_per_mps2") || r.Has("misalignment_rad")) {
    SensorModel m;
    m.bias_counts = r.Vector3("bias_counts", std::nullopt);
    m.scale_counts_per_mps2 =
        r.Vector3("scale_counts_per_mps2", std::nullopt, NumberRange::kPositive);
    if (const toml::table* mis = r.Table("misalignment_rad")) {
      TomlTableReader mr(*mis, "misalignment_rad", source);
      m.a_yz_rad = mr.Number("yz", 0.0);
      m.a_zy_rad = mr.Number("zy", 0.0);
      m.a_zx_rad = mr.Number("zx", 0.0);
      mr.Finish();
    }
    b.model = m;
  }
  const std::string fault = r.String("fault", std::string("none"));
  if (fault == "dead") {
    b.fault = BoardFault::kDead;
  } else if (fault == "loose") {
    b.fault = BoardFault::kLoose;
  } else if (fault != "none") {
    r.Fail(*r.Get("fault"), "fault", "expected \"none\", \"dead\" or \"loose\", got '" + fault + "'");
  }
  b.dead_from_s = r.Number("dead_from_s", b.dead_from_s, NumberRange::kNonNegative);
  b.loose_deg = r.Number("loose_deg", b.loose_deg, NumberRange::kPositive);
  b.loose_rock_s = r.Number("loose_rock_s", b.loose_rock_s, NumberRange::kPositive);
  if (b.fault != BoardFault::kDead && r.Has("dead_from_s")) {
    r.FailKey("dead_from_s", "only a board with fault = \"dead\" has dead_from_s");
  }
  for (const char* key : {"loose_deg", "loose_rock_s"})
    if (b.fault != BoardFault::kLoose && r.Has(key))
      r.FailKey(key, fmt::format("only a board with fault = \"loose\" has {}", key));
  return b;
}

BenchFixture ReadFixture(TomlTableReader& r, const std::string& source) {
  BenchFixture f;
  f.name = r.String("name", std::string());
  f.bias_spread_counts =
      r.Number("bias_spread_counts", f.bias_spread_counts, NumberRange::kNonNegative);
  f.scale_spread = r.Number("scale_spread", f.scale_spread, NumberRange::kNonNegative);
  f.misalignment_spread_rad =
      r.Number("misalignment_spread_rad", f.misalignment_spread_rad, NumberRange::kNonNegative);
  const toml::array* boards = r.ArrayOfTables("board");
  if (boards == nullptr || boards->empty()) {
    throw InputError(source, 0, 0, "fixture: no [[fixture.board]]");
  }
  for (std::size_t i = 0; i < boards->size(); ++i) {
    TomlTableReader br(*boards->get(i)->as_table(), fmt::format("fixture.board {}", i + 1), source);
    f.boards.push_back(ReadBoard(br, source));
    br.Finish();
  }
  return f;
}

// Reads a required or optional top-level table through its own reader and checks its keys.
template <typename Fn>
void WithTable(TomlTableReader& root, std::string_view key, bool required,
               const std::string& source, Fn&& fn) {
  const toml::table* table = root.Table(key);
  if (table == nullptr) {
    if (required) {
      throw InputError(source, 0, 0, "required table [" + std::string(key) + "] is missing");
    }
    return;
  }
  TomlTableReader reader(*table, std::string(key), source);
  fn(reader);
  reader.Finish();
}

// A bump must name a capture of the plan; known only once the plan has been read.
void CheckBumpTargets(const toml::table& doc, const Scenario& s, const std::string& source) {
  for (std::size_t i = 0; i < s.effects.bumps.size(); ++i) {
    const int target = s.effects.bumps[i].capture;
    if (target >= 0 && target < static_cast<int>(s.captures.size())) continue;
    const toml::node* node = doc["effects"]["bump"][i]["capture"].node();
    const toml::source_position at = node ? node->source().begin : toml::source_position{};
    throw InputError(source, at.line, at.column,
                     fmt::format("effects.bump {}.capture: {} is not in the plan (0..{})", i,
                                 target, s.captures.size() - 1));
  }
}

}  // namespace

Scenario ParseScenario(std::string_view toml_text, const std::string& source_name) {
  const toml::table doc = detail::ParseTomlDocument(toml_text, source_name);
  Scenario s;
  s.source_name = source_name;
  TomlTableReader root(doc, "", source_name);
  WithTable(root, "sensor", true, source_name,
            [&](TomlTableReader& r) { s.sensor = ReadSensor(r, source_name); });
  WithTable(root, "adc", true, source_name, [&](TomlTableReader& r) { s.adc = ReadAdc(r); });
  WithTable(root, "bench", false, source_name, [&](TomlTableReader& r) { s.bench = ReadBench(r); });
  WithTable(root, "effects", false, source_name, [&](TomlTableReader& r) {
    s.effects = ReadEffects(r, source_name, s.bench.temperature_c);
  });
  WithTable(root, "fixture", false, source_name,
            [&](TomlTableReader& r) { s.fixture = ReadFixture(r, source_name); });
  WithTable(root, "lab", false, source_name, [&](TomlTableReader& r) { s.lab = ReadLab(r); });
  WithTable(root, "technician", false, source_name,
            [&](TomlTableReader& r) { s.technician = ReadTechnician(r, source_name); });
  const toml::array* plan = root.ArrayOfTables("capture");
  if (plan == nullptr) throw InputError(source_name, 0, 0, "the plan has no [[capture]]");
  for (std::size_t i = 0; i < plan->size(); ++i) {
    TomlTableReader r(*plan->get(i)->as_table(), fmt::format("capture {}", i), source_name);
    s.captures.push_back(ReadCapture(r));
    r.Finish();
  }
  root.Finish();
  CheckBumpTargets(doc, s, source_name);
  // Other cross-field checks (a bump naming a capture that does not exist, ...), without a
  // position.
  if (std::string why = s.Validate(); !why.empty()) throw InputError(source_name, 0, 0, why);
  return s;
}

Scenario LoadScenario(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open scenario '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error("cannot read scenario '" + path + "'");
  return ParseScenario(text.str(), path);
}

std::string ScenarioTruthJsonText(const Scenario& scenario) {
  const SensorModel& m = scenario.sensor.model;
  nlohmann::json j;
  j["bias_counts"] = {m.bias_counts.x(), m.bias_counts.y(), m.bias_counts.z()};
  j["scale_counts_per_mps2"] = {m.scale_counts_per_mps2.x(), m.scale_counts_per_mps2.y(),
                                m.scale_counts_per_mps2.z()};
  j["misalignment_rad"] = {{"yz", m.a_yz_rad}, {"zy", m.a_zy_rad}, {"zx", m.a_zx_rad}};
  j["gravity_mps2"] = scenario.bench.gravity_mps2;
  return detail::JsonText(j) + "\n";
}

}  // namespace accelcal::sim
