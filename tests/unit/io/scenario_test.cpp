#include "accelcal/acquire/sim/scenario.h"

#include <string>

#include <gtest/gtest.h>

#include "test_support.h"

#include "accelcal/base/error.h"
#include "accelcal/io/scenario_file.h"

namespace accelcal::sim::scenario_test {
namespace {

// A small valid scenario; tests append to it or swap one line.
const std::string kMinimal = R"([sensor]
bias_counts = [2048, 2048, 2048]
scale_counts_per_mps2 = [34.8, 34.8, 34.8]
noise_counts = [1, 1, 1]

[adc]
bits = 12

[[capture]]
kind = "static"
label = "z up"
up = [0, 0, 1]
)";

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// Parses `text` expecting an InputError; returns it.
InputError ParseFails(const std::string& text) {
  return testing::ExpectInputError([&] { ParseScenario(text, "test.toml"); }, text);
}

using testing::Contains;

TEST(ScenarioParse, MinimalTakesTheDefaults) {
  const Scenario s = ParseScenario(kMinimal, "test.toml");
  EXPECT_EQ(s.source_name, "test.toml");
  EXPECT_DOUBLE_EQ(s.bench.gravity_mps2, 9.80665);
  EXPECT_DOUBLE_EQ(s.bench.placement_error_deg, 0.5);
  EXPECT_DOUBLE_EQ(s.bench.gap_s, 20.0);
  EXPECT_DOUBLE_EQ(s.bench.capture_duration_s, 10.0);
  EXPECT_DOUBLE_EQ(s.bench.temperature_c, 25.0);
  EXPECT_DOUBLE_EQ(s.sensor.model.a_yz_rad, 0.0);
  EXPECT_FALSE(s.adc.is_signed);
  EXPECT_EQ(s.adc.MaxCounts(), 4095.0);
  EXPECT_FALSE(s.effects.temperature.has_value());
  ASSERT_EQ(s.captures.size(), 1u);
  EXPECT_DOUBLE_EQ(s.CaptureDurationS(0), 10.0);
}

TEST(ScenarioParse, SignedAdcRange) {
  const Scenario s = ParseScenario(Replace(kMinimal, "bits = 12", "bits = 16\nsigned = true"), "t");
  EXPECT_EQ(s.adc.MinCounts(), -32768.0);
  EXPECT_EQ(s.adc.MaxCounts(), 32767.0);
}

TEST(ScenarioParse, UpIsNormalized) {
  const Scenario s = ParseScenario(Replace(kMinimal, "up = [0, 0, 1]", "up = [1, 1, 1]"), "t");
  EXPECT_NEAR(s.captures[0].up.norm(), 1.0, 1e-15);
  EXPECT_NEAR(s.captures[0].up.x(), 1.0 / std::sqrt(3.0), 1e-15);
}

TEST(ScenarioParse, ReadsEveryEffect) {
  const std::string text = kMinimal + R"(
[[capture]]
kind = "turntable"
label = "spin"
radius_m = 0.1
rpm = 60
radial_axis = "-y"
up_axis = "+z"
duration_s = 3.5

[effects]
quadratic_counts_per_mps2_sq = [0.1, 0.2, 0.3]
bias_temp_coeff_counts_per_c = [1, 2, 3]
scale_temp_coeff_per_c = [1e-4, 2e-4, 3e-4]
temperature = { start_c = 20, end_c = 30 }
bias_drift_counts_per_s = [0.01, 0.02, 0.03]
radius_offset_m = 0.002
rpm_scale = 0.01
size_effect_m = [0.001, 0.002, 0.003]
turntable_tilt_rad = 0.004

[[effects.bump]]
capture = 1
at_s = 1.5
peak_mps2 = 2
duration_s = 0.05
)";
  const Scenario s = ParseScenario(text, "t");
  EXPECT_EQ(s.effects.quadratic_counts_per_mps2_sq, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_EQ(s.effects.bias_temp_coeff_counts_per_c, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(s.effects.scale_temp_coeff_per_c, Eigen::Vector3d(1e-4, 2e-4, 3e-4));
  ASSERT_TRUE(s.effects.temperature.has_value());
  EXPECT_EQ(s.effects.temperature->start_c, 20.0);
  EXPECT_EQ(s.effects.temperature->end_c, 30.0);
  EXPECT_EQ(s.effects.bias_drift_counts_per_s, Eigen::Vector3d(0.01, 0.02, 0.03));
  EXPECT_EQ(s.effects.radius_offset_m, 0.002);
  EXPECT_EQ(s.effects.rpm_scale, 0.01);
  EXPECT_EQ(s.effects.size_effect_m, Eigen::Vector3d(0.001, 0.002, 0.003));
  EXPECT_EQ(s.effects.turntable_tilt_rad, 0.004);
  ASSERT_EQ(s.effects.bumps.size(), 1u);
  EXPECT_EQ(s.effects.bumps[0].capture, 1);
  EXPECT_EQ(s.effects.bumps[0].at_s, 1.5);
  EXPECT_EQ(s.effects.bumps[0].peak_mps2, 2.0);
  EXPECT_EQ(s.effects.bumps[0].duration_s, 0.05);
  const CapturePlan& spin = s.captures.at(1);
  EXPECT_EQ(spin.kind, CaptureKind::kTurntable);
  EXPECT_EQ(spin.radial_axis, SensorAxis::kMinusY);
  EXPECT_EQ(spin.up_axis, SensorAxis::kPlusZ);
  EXPECT_DOUBLE_EQ(s.CaptureDurationS(1), 3.5);
  EXPECT_DOUBLE_EQ(s.SessionDurationS(), 10.0 + 20.0 + 3.5);
}

TEST(ScenarioParse, SyntaxErrorNamesLineAndColumn) {
  const InputError e = ParseFails(Replace(kMinimal, "bits = 12", "bits = = 12"));
  EXPECT_EQ(e.file(), "test.toml");
  EXPECT_EQ(e.line(), 7);
  EXPECT_GT(e.column(), 0);
  EXPECT_TRUE(Contains(e.what(), "test.toml:7:")) << e.what();
}

TEST(ScenarioParse, WrongTypeIsRefusedWhereItStands) {
  const InputError e = ParseFails(Replace(kMinimal, "bits = 12", "bits = \"twelve\""));
  EXPECT_EQ(e.line(), 7);
  EXPECT_EQ(e.column(), 8);
  EXPECT_TRUE(Contains(e.message(), "adc.bits")) << e.what();
  EXPECT_TRUE(Contains(e.message(), "integer")) << e.what();

  const InputError vec = ParseFails(Replace(kMinimal, "[2048, 2048, 2048]", "[2048, 2048]"));
  EXPECT_EQ(vec.line(), 2);
  EXPECT_TRUE(Contains(vec.message(), "sensor.bias_counts")) << vec.what();

  const InputError element =
      ParseFails(Replace(kMinimal, "[2048, 2048, 2048]", "[2048, \"a\", 2048]"));
  EXPECT_EQ(element.line(), 2);
  EXPECT_EQ(element.column(), 22);  // the opening quote of "a"
}

TEST(ScenarioParse, UnknownKeysAreRefused) {
  const InputError top = ParseFails(kMinimal + "\n[benhc]\nseed = 3\n");
  EXPECT_TRUE(Contains(top.message(), "unknown key 'benhc'")) << top.what();
  EXPECT_EQ(top.line(), 14);

  const InputError nested = ParseFails(Replace(kMinimal, "bits = 12", "bits = 12\nsinged = true"));
  EXPECT_TRUE(Contains(nested.message(), "adc.singed")) << nested.what();
  EXPECT_EQ(nested.line(), 8);
  EXPECT_EQ(nested.column(), 1);

  const InputError in_capture =
      ParseFails(Replace(kMinimal, "up = [0, 0, 1]", "up = [0, 0, 1]\nradius = 3"));
  EXPECT_TRUE(Contains(in_capture.message(), "capture 0.radius")) << in_capture.what();

  const InputError misalignment = ParseFails(
      Replace(kMinimal, "noise_counts", "misalignment_rad = { yz = 0.1, xy = 0.2 }\nnoise_counts"));
  EXPECT_TRUE(Contains(misalignment.message(), "misalignment_rad.xy")) << misalignment.what();

  // A [[capture]] key that belongs to the other kind is a mistake too.
  EXPECT_TRUE(Contains(
      ParseFails(Replace(kMinimal, "up = [0, 0, 1]", "up = [0, 0, 1]\nrpm = 60")).message(),
      "capture 0.rpm"));
}

TEST(ScenarioParse, BadKindIsRefused) {
  const InputError e = ParseFails(Replace(kMinimal, "kind = \"static\"", "kind = \"statik\""));
  EXPECT_EQ(e.line(), 10);
  EXPECT_TRUE(Contains(e.message(), "statik")) << e.what();
}

std::string Turntable(const std::string& radial, const std::string& up) {
  return kMinimal +
         "\n[[capture]]\nkind = \"turntable\"\nlabel = \"t\"\nradius_m = 0.1\nrpm = 60\n"
         "radial_axis = \"" +
         radial + "\"\nup_axis = \"" + up + "\"\n";
}

TEST(ScenarioParse, RadialAxisMustBePerpendicularToUp) {
  const InputError same = ParseFails(Turntable("+x", "+x"));
  EXPECT_TRUE(Contains(same.message(), "perpendicular")) << same.what();
  EXPECT_EQ(same.line(), 20);
  EXPECT_TRUE(Contains(ParseFails(Turntable("+z", "-z")).message(), "perpendicular"));
  EXPECT_TRUE(Contains(ParseFails(Turntable("x", "+z")).message(), "+x -x"));
  EXPECT_NO_THROW(ParseScenario(Turntable("-z", "+y"), "t"));
}

TEST(ScenarioParse, OutOfRangeValuesAreRefused) {
  const InputError noise =
      ParseFails(Replace(kMinimal, "noise_counts = [1, 1, 1]", "noise_counts = [1, -1, 1]"));
  EXPECT_EQ(noise.line(), 4);
  EXPECT_EQ(noise.column(), 20);
  EXPECT_TRUE(Contains(noise.message(), "negative")) << noise.what();

  EXPECT_TRUE(
      Contains(ParseFails(Replace(kMinimal, "[34.8, 34.8, 34.8]", "[34.8, 0, 34.8]")).message(),
               "positive"));
  EXPECT_TRUE(
      Contains(ParseFails(Replace(kMinimal, "bits = 12", "bits = 40")).message(), "between"));
  EXPECT_TRUE(Contains(ParseFails(Replace(kMinimal, "up = [0, 0, 1]", "up = [0, 0, 0]")).message(),
                       "zero"));
  EXPECT_TRUE(Contains(ParseFails(kMinimal + "[bench]\ngap_s = -1\n").message(), "bench.gap_s"));
  const InputError bump = ParseFails(
      kMinimal + "[[effects.bump]]\ncapture = 5\nat_s = 1\npeak_mps2 = 1\nduration_s = 0.1\n");
  EXPECT_TRUE(Contains(bump.message(), "effects.bump 0.capture: 5")) << bump.what();
  EXPECT_EQ(bump.line(), 14);
}

TEST(ScenarioParse, MissingPiecesAreNamed) {
  EXPECT_TRUE(Contains(ParseFails(Replace(kMinimal, "bits = 12", "")).message(), "adc.bits"));
  EXPECT_TRUE(Contains(ParseFails(Replace(kMinimal, "label = \"z up\"", "")).message(), "label"));
  const std::string no_plan = kMinimal.substr(0, kMinimal.find("[[capture]]"));
  EXPECT_TRUE(Contains(ParseFails(no_plan).message(), "[[capture]]"));
  EXPECT_TRUE(Contains(ParseFails(no_plan.substr(no_plan.find("[adc]"))).message(), "[sensor]"));
}

TEST(ScenarioLoad, MissingFileIsAnErrorNamingThePath) {
  try {
    LoadScenario("/nonexistent/scenario.toml");
    FAIL() << "no error";
  } catch (const InputError&) {
    FAIL() << "a missing file is not malformed input";
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "/nonexistent/scenario.toml"));
  }
}

void ExpectSameScenario(const Scenario& a, const Scenario& b) {
  EXPECT_EQ(a.sensor.model.ToVector(), b.sensor.model.ToVector());
  EXPECT_EQ(a.sensor.noise_counts, b.sensor.noise_counts);
  EXPECT_EQ(a.sensor.rate_hz, b.sensor.rate_hz);
  EXPECT_EQ(a.adc.bits, b.adc.bits);
  EXPECT_EQ(a.adc.is_signed, b.adc.is_signed);
  EXPECT_EQ(a.bench.gravity_mps2, b.bench.gravity_mps2);
  EXPECT_EQ(a.bench.seed, b.bench.seed);
  EXPECT_EQ(a.bench.placement_error_deg, b.bench.placement_error_deg);
  EXPECT_EQ(a.bench.gap_s, b.bench.gap_s);
  EXPECT_EQ(a.bench.capture_duration_s, b.bench.capture_duration_s);
  EXPECT_EQ(a.bench.temperature_c, b.bench.temperature_c);
  EXPECT_EQ(a.bench.recording_quiet_start_s, b.bench.recording_quiet_start_s);
  EXPECT_EQ(a.bench.move_s, b.bench.move_s);
  EXPECT_EQ(a.effects.quadratic_counts_per_mps2_sq, b.effects.quadratic_counts_per_mps2_sq);
  EXPECT_EQ(a.effects.radius_offset_m, b.effects.radius_offset_m);
  EXPECT_EQ(a.effects.turntable_tilt_rad, b.effects.turntable_tilt_rad);
  EXPECT_EQ(a.effects.temperature.has_value(), b.effects.temperature.has_value());
  EXPECT_EQ(a.effects.bumps.size(), b.effects.bumps.size());
  EXPECT_EQ(a.lab.gravity, b.lab.gravity);
  EXPECT_EQ(a.lab.gravity_sigma_mps2, b.lab.gravity_sigma_mps2);
  EXPECT_EQ(a.lab.equipment, b.lab.equipment);
  ASSERT_EQ(a.captures.size(), b.captures.size());
  for (std::size_t i = 0; i < a.captures.size(); ++i) {
    SCOPED_TRACE("capture " + std::to_string(i));
    const CapturePlan& x = a.captures[i];
    const CapturePlan& y = b.captures[i];
    EXPECT_EQ(x.kind, y.kind);
    EXPECT_EQ(x.label, y.label);
    EXPECT_LT((x.up - y.up).norm(), 1e-15);
    EXPECT_EQ(std::isnan(x.radius_m), std::isnan(y.radius_m));
    if (!std::isnan(x.radius_m)) {
      EXPECT_EQ(x.radius_m, y.radius_m);
    }
    if (!std::isnan(x.rpm)) {
      EXPECT_EQ(x.rpm, y.rpm);
    }
    EXPECT_EQ(x.radial_axis, y.radial_axis);
    EXPECT_EQ(x.up_axis, y.up_axis);
    EXPECT_EQ(std::isnan(x.duration_s), std::isnan(y.duration_s));
  }
}

TEST(DefaultScenario, EqualsTheShippedFile) {
  const Scenario file = LoadScenario(ACCELCAL_SOURCE_DIR "/scenarios/bench_default.toml");
  ExpectSameScenario(DefaultScenario(), file);
}

TEST(DefaultScenario, HasTheDocumentedShape) {
  const Scenario s = DefaultScenario();
  EXPECT_TRUE(s.Validate().empty()) << s.Validate();
  EXPECT_EQ(s.adc.bits, 12);
  EXPECT_NEAR(s.sensor.model.scale_counts_per_mps2.mean(), 2048.0 / (6.0 * 9.80665), 0.5);
  int statics = 0, turntables = 0;
  for (const CapturePlan& c : s.captures) (c.kind == CaptureKind::kStatic ? statics : turntables)++;
  EXPECT_EQ(statics, 9);
  EXPECT_EQ(turntables, 9);
  // No two static poses alike.
  for (std::size_t i = 0; i < s.captures.size(); ++i) {
    for (std::size_t j = i + 1; j < s.captures.size(); ++j) {
      if (s.captures[i].kind != CaptureKind::kStatic || s.captures[j].kind != CaptureKind::kStatic)
        continue;
      EXPECT_GT((s.captures[i].up - s.captures[j].up).norm(), 0.1) << i << " " << j;
    }
  }
  EXPECT_FALSE(s.effects.temperature.has_value());
  EXPECT_EQ(s.effects.quadratic_counts_per_mps2_sq, Eigen::Vector3d::Zero());
}

// The virtual bench's lab (issue 27): what the welcome offers on the virtual bench.
TEST(ScenarioParse, TheLabIsAGoodOneUnlessTheScenarioSaysOtherwise) {
  const Scenario good = ParseScenario(kMinimal, "t");
  EXPECT_EQ(good.lab.GravityAnswer(9.7803), "9.78030 +- 2e-05");
  EXPECT_TRUE(Contains(good.lab.equipment, "ruler id SIM-RUL-01 u 0.03 cal ")) << good.lab.equipment;
  const Scenario unknown = ParseScenario(kMinimal + "[lab]\ngravity = \"standard\"\nequipment = \"keep\"\n", "t");
  EXPECT_EQ(unknown.lab.GravityAnswer(9.7803), "standard");
  EXPECT_EQ(unknown.lab.equipment, "keep");
  EXPECT_TRUE(Contains(ParseFails(kMinimal + "[lab]\nruler = 1\n").what(), "ruler"));
}

TEST(ShippedScenarios, EffectsDemoLoadsWithItsEffectsOn) {
  const Scenario s = LoadScenario(ACCELCAL_SOURCE_DIR "/scenarios/effects_demo.toml");
  EXPECT_GT(s.effects.quadratic_counts_per_mps2_sq.norm(), 0.0);
  EXPECT_GT(s.effects.radius_offset_m, 0.0);
  EXPECT_EQ(s.captures.size(), DefaultScenario().captures.size());
}

TEST(SensorAxis, RoundTripsThroughStrings) {
  for (const char* name : {"+x", "-x", "+y", "-y", "+z", "-z"}) {
    const std::optional<SensorAxis> axis = StringToSensorAxis(name);
    ASSERT_TRUE(axis.has_value()) << name;
    EXPECT_EQ(SensorAxisToString(*axis), name);
    EXPECT_DOUBLE_EQ(SensorAxisVector(*axis).norm(), 1.0);
  }
  EXPECT_FALSE(StringToSensorAxis("x").has_value());
  EXPECT_EQ(SensorAxisVector(SensorAxis::kMinusY), Eigen::Vector3d(0, -1, 0));
}

}  // namespace
}  // namespace accelcal::sim::scenario_test
