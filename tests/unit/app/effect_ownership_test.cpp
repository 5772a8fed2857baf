// An effect owns what is said and written of it (issue 28): an effect defined only here, and
// registered from here (EffectRegistration), is read, put in words, reported and exported from
// what it declares, with no other file knowing its name.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "accelcal/app/wizard/diagnosis_words.h"
#include "accelcal/base/error.h"
#include "accelcal/calibration/apply.h"
#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/io/export/ardupilot_params.h"
#include "accelcal/io/export/c_header.h"
#include "accelcal/io/export/calibration_csv.h"
#include "accelcal/report/report_model.h"
#include "accelcal/report/report_text.h"
#include "export_test_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

// What the effects of this test share: three parameters, one per axis, identifiable and
// plausible whatever the captures, properties of the sensor corrected first.
template <class Derived>
class SensorTestEffect : public DifferentiableEffect<Derived> {
 public:
  explicit SensorTestEffect(std::string stem) : stem_(std::move(stem)) {}
  int NumParameters() const override { return 3; }
  std::string ParameterName(int i) const override { return stem_ + "_" + "xyz"[i]; }
  double ParameterScale(int, const SensorModel&, const EffectContext&) const override { return 1e-3; }
  std::string WhyNotIdentifiable(const std::vector<FitCapture>&) const override { return {}; }
  std::string WhyImplausible(const double*, const SensorModel&, const std::vector<FitCapture>&) const override {
    return {};
  }
  int CorrectionStage() const override { return 0; }
  bool CorrectsReadings() const override { return true; }

 private:
  std::string stem_;
};

// The zero-g level settling after power-up: b_j + a_j exp(-t / 300 s). A property of the sensor
// (apply corrects readings with it), but accelcal_correct in the C header is not given the time
// since power-up: the header cannot carry it, and says so.
class WarmupBias final : public SensorTestEffect<WarmupBias> {
 public:
  WarmupBias() : SensorTestEffect("warmup") {}
  std::string_view Name() const override { return "warmup_bias"; }
  std::string_view Story() const override { return "the zero-g level settles after power-up"; }
  std::string ParameterUnit(int) const override { return "counts"; }
  std::string_view CapturePlan() const override { return "captures from power-up on"; }
  template <class S, class Base>
  void Apply(const S* a, const Base&, const FitCapture& c, const EffectContext&, CorrectedCaptureOf<S>* out) const {
    for (int j = 0; j < 3; ++j) out->raw_counts(j) -= a[j] * std::exp(-c.mean_t_s / 300.0);
  }
};

// The zero-g level bending with temperature: b_j + tq_j (T - T_ref)^2, a sensor's property with a
// C form of its own.
class TemperatureCurvature final : public SensorTestEffect<TemperatureCurvature> {
 public:
  TemperatureCurvature() : SensorTestEffect("tq") {}
  std::string_view Name() const override { return "temperature_curvature"; }
  std::string_view Story() const override { return "the zero-g level bends with temperature"; }
  std::string ParameterUnit(int) const override { return "counts/degC^2"; }
  std::string_view CapturePlan() const override { return "captures at three temperatures or more"; }
  template <class S, class Base>
  void Apply(const S* tq, const Base&, const FitCapture& c, const EffectContext& ctx, CorrectedCaptureOf<S>* out) const {
    const double dt_c = c.mean_temp_c - ctx.temp_ref_c;
    for (int j = 0; j < 3; ++j) out->raw_counts(j) -= tq[j] * dt_c * dt_c;
  }
  bool ReadsTemperature() const override { return true; }
  std::string_view PlainName() const override { return "a zero-g level bending with temperature"; }
  std::optional<BenchStatement> InBenchTerms(std::span<const double> tq, std::span<const double>, std::string_view,
                                             double) const override {
    BenchStatement s{"the zero-g level bends with temperature: ", {}, " 10 degC off the reference"};
    s.size.shape = BenchQuantity::Shape::kPerAxis;
    for (double v : tq) s.size.values.push_back(v * 100.0);  // tq (10 degC)^2
    s.size.unit = "counts";
    s.size.decimals = 2;
    return s;
  }
  std::string_view ReportNote() const override {
    return "seen only where the captures' temperatures spread on both sides of the reference.";
  }
  std::optional<CCorrection> InC() const override {
    return CCorrection{{{"temperature_curvature: tq (counts per degC^2)", "accelcal_tq_counts_per_degc2",
                         {"tq_x", "tq_y", "tq_z"}}},
                       "  for (j = 0; j < 3; ++j) d[j] -= accelcal_tq_counts_per_degc2[j] * dt_c * dt_c;\n",
                       false, {}};
  }
};

CalibrationEffect Adopted(const Effect& effect, const std::vector<double>& values) {
  CalibrationEffect e;
  e.name = std::string(effect.Name());
  for (int i = 0; i < effect.NumParameters(); ++i)
    e.parameters.push_back({effect.ParameterName(i), effect.ParameterUnit(i), values[static_cast<size_t>(i)], kNaN});
  e.corrects_readings = effect.CorrectsReadings();
  return e;
}

// The defect of issue 28: the C header wrote any sensor effect it did not know as the quadratic
// nonlinearity (here a second time, beside the real one: the header compiled and corrected
// readings wrongly, silently). It must refuse the effect by name.
TEST(EffectOwnership, TheCHeaderRefusesByNameASensorEffectItCannotCarry) {
  const WarmupBias warmup;
  const EffectRegistration registered(warmup);
  Calibration cal = testing::ExportTestCalibrationWithEffects();
  cal.effects.push_back(Adopted(warmup, {1.5, -0.5, 0.25}));
  try {
    const std::string header = ExportCHeader(cal, {}).text;
    FAIL() << "exported:\n" << header;
  } catch (const Error& e) {
    EXPECT_TRUE(testing::Contains(e.what(), "'warmup_bias'")) << e.what();
    EXPECT_TRUE(testing::Contains(e.what(), "C header cannot carry")) << e.what();
  }
}

// The header `cal` exports, compiled by the system's C compiler (double arithmetic) and run on
// `readings`: what it makes of each.
std::vector<Eigen::Vector3d> CorrectedByTheHeader(const Calibration& cal, const std::vector<Sample>& readings) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / fmt::format("accelcal_effect_ownership_{}", ::getpid());
  fs::create_directories(dir);
  std::ofstream(dir / "cal.h") << ExportCHeader(cal, {}).text;
  std::ofstream(dir / "main.c")
      << "#define ACCELCAL_REAL double\n#include <stdio.h>\n#include \"cal.h\"\n"
      << "int main(void) {\n  double x, y, z, t, a[3];\n"
      << "  while (scanf(\"%lf %lf %lf %lf\", &x, &y, &z, &t) == 4) {\n"
      << "    accelcal_correct(x, y, z, t, a);\n    printf(\"%.17g %.17g %.17g\\n\", a[0], a[1], a[2]);\n  }\n"
      << "  return 0;\n}\n";
  std::ofstream in(dir / "in.txt");
  for (const Sample& s : readings)
    in << fmt::format("{} {} {} {}\n", s.raw_counts.x(), s.raw_counts.y(), s.raw_counts.z(), s.temp_c);
  in.close();
  std::vector<Eigen::Vector3d> out;
  if (std::system(fmt::format("cc -std=c99 -Wall -Wextra -Werror -pedantic -o {0}/prog {0}/main.c -lm && "
                              "{0}/prog < {0}/in.txt > {0}/out.txt", dir.string()).c_str()) == 0) {
    std::ifstream result(dir / "out.txt");
    for (Eigen::Vector3d a; result >> a.x() >> a.y() >> a.z();) out.push_back(a);
  }
  fs::remove_all(dir);
  return out;
}

// An effect of the sensor with a C form: the header declares its constant, runs its statements
// in correction order (before the temperature scale and the quadratic, stage 0), takes the
// temperature it reads, and corrects readings as `accelcal apply` does.
TEST(EffectOwnership, TheCHeaderCarriesASensorEffectInTheCFormItStates) {
  const TemperatureCurvature curvature;
  const EffectRegistration registered(curvature);
  Calibration cal = testing::ExportTestCalibrationWithEffects();
  cal.effects.push_back(Adopted(curvature, {0.01, -0.02, 0.005}));
  const ExportResult r = ExportCHeader(cal, {});
  EXPECT_TRUE(r.cannot_hold.empty());
  EXPECT_TRUE(testing::Contains(r.text, "static const ACCELCAL_REAL accelcal_tq_counts_per_degc2[3] = {0.01, -0.02, 0.005};"))
      << r.text;
  EXPECT_LT(r.text.find("accelcal_tq_counts_per_degc2[j] * dt_c"), r.text.find("temperature_scale: the sensitivity"));
  std::vector<Sample> readings;
  for (int i = 0; i < 20; ++i) {
    Sample s;
    s.raw_counts = Eigen::Vector3d(1700.0 + 37.0 * i, 2400.0 - 29.0 * i, 2050.0 + 13.0 * (i % 7));
    s.temp_c = 10.0 + 1.5 * i;
    readings.push_back(s);
  }
  const std::vector<Eigen::Vector3d> got = CorrectedByTheHeader(cal, readings);
  ASSERT_EQ(got.size(), readings.size());
  const CalibrationApplier applier(cal);
  for (size_t i = 0; i < readings.size(); ++i)
    EXPECT_LT((got[i] - applier.Apply(readings[i])).norm(), 1e-9) << i;
}

AdoptedEffect Found(const Effect& effect, std::vector<double> values, std::vector<double> sigmas) {
  AdoptedEffect a;
  a.name = std::string(effect.Name());
  for (int i = 0; i < effect.NumParameters(); ++i) {
    a.parameter_names.push_back(effect.ParameterName(i));
    a.parameter_units.push_back(effect.ParameterUnit(i));
  }
  a.parameters = std::move(values);
  a.uncertainty = std::move(sigmas);
  return a;
}

// What the technician is told: the registered effect's own statement and name, rendered as the
// library's; one that states nothing is named with its parameters.
TEST(EffectOwnership, ARegisteredEffectIsSaidInItsOwnBenchWords) {
  const TemperatureCurvature curvature;
  const WarmupBias warmup;
  const EffectRegistration registered(curvature), also(warmup);
  const AdoptedEffect bend = Found(curvature, {0.01, -0.02, 0.005}, {0.001, 0.001, 0.001});
  // tq (10 degC)^2 = 100 tq counts.
  EXPECT_EQ(EffectInPlainWords(bend, 9.80665),
            "the zero-g level bends with temperature: x +1.00, y -2.00, z +0.50 counts 10 degC off the reference");
  EXPECT_EQ(PlainEffectName("temperature_curvature"), "a zero-g level bending with temperature");
  EXPECT_FALSE(IsBenchError("temperature_curvature"));
  DiagnosisReport r;
  r.adopted = {bend};
  const DiagnosisWords w = DiagnosisInPlainWords(r, 9.80665);
  EXPECT_EQ(w.prompt, "The zero-g level bends with temperature: x +1.00, y -2.00, z +0.50 counts 10 degC off the "
                      "reference: add it to the calibration (recommended), or keep the basic model?");
  EXPECT_EQ(EffectInPlainWords(Found(warmup, {1.5, -0.5, 0.25}, {}), 9.80665),
            "an effect the basic model lacks (warmup_bias): warmup_x 1.5 counts, warmup_y -0.5 counts, warmup_z 0.25 counts");
  EXPECT_EQ(PlainEffectName("warmup_bias"), "warmup_bias");
}

// The report: its rows (parameters with units and 1-sigma, whether it corrects readings), its
// own note beside the nine parameters.
TEST(EffectOwnership, ARegisteredEffectIsReportedWithItsOwnNote) {
  const TemperatureCurvature curvature;
  const EffectRegistration registered(curvature);
  ReportInputs in;
  in.calibration = testing::ExportTestCalibration();
  CalibrationEffect e = Adopted(curvature, {0.01, -0.02, 0.005});
  e.parameters[0].sigma = 0.002;
  in.calibration.effects.push_back(e);
  const ReportModel m = BuildReportModel(in);
  ASSERT_EQ(m.effects.size(), 1u);
  EXPECT_TRUE(m.effects[0].corrects_readings);
  ASSERT_EQ(m.effects[0].parameters.size(), 3u);
  EXPECT_EQ(m.effects[0].parameters[0].unit, "counts/degC^2");
  EXPECT_EQ(m.parameter_notes.back(), "temperature_curvature: seen only where the captures' temperatures spread on "
                                      "both sides of the reference.");
  EXPECT_FALSE(TakesGravityErrorForItsOwn("temperature_curvature"));
  const std::string text = RenderReportText(m);
  EXPECT_TRUE(testing::Contains(text, "Effect: temperature_curvature (corrects readings)")) << text;
  EXPECT_TRUE(testing::Contains(text, "0.002")) << text;
}

// The other exports: a per-axis offset and scale cannot hold it and says so by name; CSV
// carries its parameters.
TEST(EffectOwnership, TheFlightStacksNameARegisteredEffectTheyCannotHoldAndCsvCarriesIt) {
  const WarmupBias warmup;
  const EffectRegistration registered(warmup);
  Calibration cal = testing::ExportTestCalibration();
  cal.effects.push_back(Adopted(warmup, {1.5, -0.5, 0.25}));
  DriverScaleOptions driver;
  driver.nominal_scale_counts_per_mps2 = Eigen::Vector3d::Constant(34.8);
  const ExportResult ardupilot = ExportArduPilotParams(cal, driver, {});
  ASSERT_EQ(ardupilot.cannot_hold.size(), 2u);
  EXPECT_TRUE(testing::Contains(ardupilot.cannot_hold[1], "the sensor effects warmup_bias")) << ardupilot.cannot_hold[1];
  EXPECT_TRUE(testing::Contains(ExportCalibrationCsv(cal).text, "warmup_bias.warmup_y,-0.5,,counts\r\n"));
}

TEST(EffectOwnership, ARegistrationEndsWithItsLifeAndRefusesATakenName) {
  {
    const WarmupBias warmup;
    const EffectRegistration registered(warmup);
    EXPECT_EQ(FindEffect("warmup_bias"), &warmup);
    EXPECT_THROW(EffectRegistration again(warmup), Error);
  }
  EXPECT_EQ(FindEffect("warmup_bias"), nullptr);
  EXPECT_EQ(KnownEffects().size(), AllEffects().size());
}

}  // namespace
}  // namespace accelcal
