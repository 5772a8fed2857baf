// The C header export: golden text, and the header really compiled with the system C compiler
// (cc -std=c99 -Wall -Wextra -Werror -pedantic) into a small program whose output is compared
// with CalibrationApplier on many raw readings.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "accelcal/calibration/apply.h"
#include "accelcal/io/export/c_header.h"
#include "export_test_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

namespace fs = std::filesystem;
using testing::ExportTestCalibration;
using testing::ExportTestCalibrationWithEffects;

TEST(ExportCHeader, MatchesGoldenText) {
  ExportContext context{"SIM-0001", "2025-03-01T14:05:09.000Z", ""};
  const ExportResult base = ExportCHeader(ExportTestCalibration(), context);
  testing::ExpectMatchesGolden("c_header_base.h", base.text);
  EXPECT_TRUE(base.cannot_hold.empty());
  const ExportResult effects = ExportCHeader(ExportTestCalibrationWithEffects(), context);
  testing::ExpectMatchesGolden("c_header_effects.h", effects.text);
  EXPECT_TRUE(effects.cannot_hold.empty()) << effects.cannot_hold[0];
  // The session's effect is said, not dropped silently.
  ASSERT_EQ(effects.notes.size(), 3u);
  EXPECT_TRUE(testing::Contains(effects.notes[0], "radius_offset is not exported"));
}

TEST(ExportCHeader, CorrectionMatrixIsTTimesKInverse) {
  const SensorModel m = ExportTestCalibration().model;
  const Eigen::Vector3d raw(2100.0, 1990.0, 2380.0);
  const Eigen::Vector3d expected = m.Calibrate(raw);
  EXPECT_LT((CorrectionMatrix(m) * (raw - m.bias_counts) - expected).norm(), 1e-12);
}

// Raw readings (and temperatures) spread over what the sensor sees: specific forces of
// magnitude up to 2 g in every direction, temperatures 10..40 degC.
std::vector<Sample> Readings(const SensorModel& m, int n) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> magnitude(0.0, 2.0 * 9.80665), temp(10.0, 40.0);
  std::vector<Sample> out;
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d f(normal(rng), normal(rng), normal(rng));
    Sample s;
    s.raw_counts = m.Raw(f.normalized() * magnitude(rng)).array().round();  // ADC counts
    s.temp_c = temp(rng);
    out.push_back(s);
  }
  return out;
}

class CompiledHeader : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("accelcal_c_header_{}", ::getpid());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Writes the header and a program that corrects "x y z [t]" lines; compiles it with
  // ACCELCAL_REAL = `real`; returns the program's output for `readings`.
  std::vector<Eigen::Vector3d> Run(const Calibration& cal, const std::string& real, bool with_temp,
                                   const std::vector<Sample>& readings) {
    std::ofstream(dir_ / "accel_cal.h") << ExportCHeader(cal, {}).text;
    std::ofstream(dir_ / "main.c")
        << "#define ACCELCAL_REAL " << real << "\n#include <stdio.h>\n#include \"accel_cal.h\"\n"
        << "int main(void) {\n  double x, y, z, t;\n  ACCELCAL_REAL a[3];\n"
        << "  while (scanf(\"%lf %lf %lf %lf\", &x, &y, &z, &t) == 4) {\n"
        << (with_temp ? "    accelcal_correct((ACCELCAL_REAL)x, (ACCELCAL_REAL)y, (ACCELCAL_REAL)z, (ACCELCAL_REAL)t, a);\n"
                      : "    (void)t;\n    accelcal_correct((ACCELCAL_REAL)x, (ACCELCAL_REAL)y, (ACCELCAL_REAL)z, a);\n")
        << "    printf(\"%.17g %.17g %.17g\\n\", (double)a[0], (double)a[1], (double)a[2]);\n  }\n  return 0;\n}\n";
    std::ofstream in(dir_ / "in.txt");
    for (const Sample& s : readings)
      in << fmt::format("{} {} {} {}\n", s.raw_counts.x(), s.raw_counts.y(), s.raw_counts.z(), s.temp_c);
    in.close();
    const std::string compile = fmt::format("cc -std=c99 -Wall -Wextra -Werror -pedantic -o {0}/prog {0}/main.c -lm 2> {0}/cc.log",
                                            dir_.string());
    if (std::system(compile.c_str()) != 0) {
      std::ifstream log(dir_ / "cc.log");
      std::stringstream text;
      text << log.rdbuf();
      ADD_FAILURE() << "the header did not compile:\n" << text.str();
      return {};
    }
    EXPECT_EQ(std::system(fmt::format("{0}/prog < {0}/in.txt > {0}/out.txt", dir_.string()).c_str()), 0);
    std::ifstream out(dir_ / "out.txt");
    std::vector<Eigen::Vector3d> result;
    Eigen::Vector3d a;
    while (out >> a.x() >> a.y() >> a.z()) result.push_back(a);
    return result;
  }

  // Largest |program - CalibrationApplier| over `readings`, m/s^2.
  double MaxError(const Calibration& cal, const std::string& real, bool with_temp) {
    const std::vector<Sample> readings = Readings(cal.model, 400);
    const std::vector<Eigen::Vector3d> got = Run(cal, real, with_temp, readings);
    EXPECT_EQ(got.size(), readings.size());
    const CalibrationApplier applier(cal);
    double worst = 0.0;
    for (size_t i = 0; i < std::min(got.size(), readings.size()); ++i)
      worst = std::max(worst, (got[i] - applier.Apply(readings[i])).norm());
    return got.empty() ? INFINITY : worst;
  }

  fs::path dir_;
};

TEST_F(CompiledHeader, DoubleAgreesWithApplyToRounding) {
  EXPECT_LT(MaxError(ExportTestCalibration(), "double", false), 1e-9);
}

TEST_F(CompiledHeader, FloatAgreesWithApplyToFloatPrecision) {
  // float: the bias is rounded to ~1.2e-4 counts near 2048, i.e. ~4e-6 m/s^2, plus M's rounding.
  EXPECT_LT(MaxError(ExportTestCalibration(), "float", false), 5e-5);
}

TEST_F(CompiledHeader, EffectsWithTemperatureAgreeWithApply) {
  EXPECT_LT(MaxError(ExportTestCalibrationWithEffects(), "double", true), 1e-9);
  EXPECT_LT(MaxError(ExportTestCalibrationWithEffects(), "float", true), 5e-5);
}

TEST_F(CompiledHeader, CompilesCleanWhenOnlyIncluded) {
  std::ofstream(dir_ / "accel_cal.h") << ExportCHeader(ExportTestCalibrationWithEffects(), {}).text;
  std::ofstream(dir_ / "main.c") << "#include \"accel_cal.h\"\n#include \"accel_cal.h\"\nint main(void) { return 0; }\n";
  EXPECT_EQ(std::system(fmt::format("cc -std=c99 -Wall -Wextra -Werror -pedantic -o {0}/prog {0}/main.c -lm",
                                    dir_.string()).c_str()), 0);
}

TEST(ExportCHeader, RefusesAnUnknownEffect) {
  Calibration cal = ExportTestCalibration();
  CalibrationEffect unknown;
  unknown.name = "flux_capacitor";
  cal.effects.push_back(unknown);
  try {
    ExportCHeader(cal, {});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(testing::Contains(e.what(), "'flux_capacitor'")) << e.what();
  }
}

}  // namespace
}  // namespace accelcal
