// The Kalibr imu.yaml and CSV exports: golden text, and parsed back (YAML line by line with a
// tiny parser of Kalibr's flat `key: value  # comment` file; CSV with the RFC 4180 splitter).
#include <cmath>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "accelcal/io/csv_fields.h"
#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/export/calibration_csv.h"
#include "accelcal/io/export/kalibr_imu_yaml.h"
#include "export_test_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

using testing::Contains;
using testing::ExportTestCalibration;
using testing::ExportTestCalibrationWithEffects;

// Kalibr's imu.yaml is a flat mapping: `key: scalar`, '#' starts a comment.
std::map<std::string, std::string> ParseFlatYaml(const std::string& text) {
  std::map<std::string, std::string> m;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    while (!line.empty() && line.back() == ' ') line.pop_back();
    if (line.empty()) continue;
    const size_t colon = line.find(": ");
    EXPECT_NE(colon, std::string::npos) << line;
    EXPECT_EQ(line.find_first_of(" \t"), colon + 1) << "key with a blank: " << line;
    EXPECT_TRUE(m.emplace(line.substr(0, colon), line.substr(colon + 2)).second) << line;
  }
  return m;
}

KalibrImuYamlOptions Figures() {
  KalibrImuYamlOptions o;
  o.accelerometer_noise_density = 0.0018;
  o.accelerometer_random_walk = 4.5e-05;
  o.update_rate_hz = 100.0;
  o.comment = "Kalibr IMU noise model by accelcal export-cal: device SIM-0001.";
  return o;
}

TEST(ExportKalibr, MatchesGoldenText) {
  testing::ExpectMatchesGolden("kalibr_imu.yaml", WriteKalibrImuYaml(Figures()).text);
}

TEST(ExportKalibr, ParsesBackWithoutTheUnknownGyroscope) {
  const ExportResult r = WriteKalibrImuYaml(Figures());
  const auto m = ParseFlatYaml(r.text);
  EXPECT_EQ(m.size(), 4u);
  EXPECT_EQ(std::stod(m.at("accelerometer_noise_density")), 0.0018);
  EXPECT_EQ(std::stod(m.at("accelerometer_random_walk")), 4.5e-05);
  EXPECT_EQ(m.at("update_rate"), "100.0");  // a float, as Kalibr expects
  EXPECT_EQ(m.at("rostopic"), "/imu0");
  EXPECT_EQ(m.count("gyroscope_noise_density"), 0u);
  ASSERT_EQ(r.cannot_hold.size(), 2u);
  EXPECT_TRUE(Contains(r.cannot_hold[0], "gyroscope_noise_density")) << r.cannot_hold[0];
}

TEST(ExportKalibr, WritesTheGyroscopeWhenGiven) {
  KalibrImuYamlOptions o = Figures();
  o.gyroscope_noise_density = 1.7e-4;
  o.gyroscope_random_walk = 2e-5;
  o.rostopic = "/board7/imu";
  const ExportResult r = WriteKalibrImuYaml(o);
  const auto m = ParseFlatYaml(r.text);
  EXPECT_EQ(m.size(), 6u);
  EXPECT_EQ(std::stod(m.at("gyroscope_noise_density")), 1.7e-4);
  EXPECT_EQ(m.at("rostopic"), "/board7/imu");
  EXPECT_EQ(r.cannot_hold.size(), 1u);
}

TEST(ExportKalibr, RefusesMissingOrBadFigures) {
  KalibrImuYamlOptions o = Figures();
  o.accelerometer_random_walk = kNaN;
  EXPECT_TRUE(Contains(o.Validate(), "random walk"));
  o = Figures();
  o.update_rate_hz = 0.0;
  EXPECT_TRUE(Contains(o.Validate(), "update rate"));
  o = Figures();
  o.rostopic = "/imu 0";
  EXPECT_TRUE(Contains(o.Validate(), "ROS topic"));
  EXPECT_THROW(WriteKalibrImuYaml(o), Error);
}

nlohmann::json Allan(const std::string& unit) {
  auto axis = [](double n, nlohmann::json k) {
    return nlohmann::json{{"noise_density", n}, {"bias_instability", 0.1}, {"random_walk", k},
                          {"tau_s", {1, 2}}, {"adev", {1, 0.7}}};
  };
  return {{"unit", unit}, {"rate_hz", 200.0},
          {"axes", {{"x", axis(0.05, 0.002)}, {"y", axis(0.07, nullptr)}, {"z", axis(0.06, 0.003)}}}};
}

TEST(ExportKalibr, AllanFiguresInCountsAreScaledAndTheWorstAxisTaken) {
  const Calibration cal = ExportTestCalibration();  // scale 34.1, 35.2, 34.6 counts per m/s^2
  const AllanNoiseFigures f = AllanNoiseForKalibr(Allan("counts"), cal, "allan.json");
  // noise: x 0.05/34.1 = 1.466e-3, y 0.07/35.2 = 1.989e-3, z 0.06/34.6 = 1.734e-3 -> y
  EXPECT_DOUBLE_EQ(f.noise_density_mps2_per_sqrt_hz, 0.07 / 35.2);
  EXPECT_EQ(f.noise_density_axis, 'y');
  // random walk: y has none; x 0.002/34.1, z 0.003/34.6 -> z
  EXPECT_DOUBLE_EQ(f.random_walk_mps3_per_sqrt_hz, 0.003 / 34.6);
  EXPECT_EQ(f.random_walk_axis, 'z');
  EXPECT_EQ(f.rate_hz, 200.0);
  const AllanNoiseFigures si = AllanNoiseForKalibr(Allan("m/s^2"), cal, "allan.json");
  EXPECT_EQ(si.noise_density_mps2_per_sqrt_hz, 0.07);
}

TEST(ExportKalibr, MalformedAllanFileIsRefusedByField) {
  const Calibration cal = ExportTestCalibration();
  nlohmann::json a = Allan("g");
  EXPECT_TRUE(Contains(testing::ExpectInputError([&] { AllanNoiseForKalibr(a, cal, "allan.json"); }, a.dump()).what(),
                       "allan.json"));
  a = Allan("counts");
  a["axes"]["z"]["noise_density"] = -1.0;
  EXPECT_TRUE(Contains(testing::ExpectInputError([&] { AllanNoiseForKalibr(a, cal, "allan.json"); }, a.dump()).what(),
                       "axes.z.noise_density"));
  a = Allan("counts");
  a["axes"].erase("y");
  EXPECT_TRUE(Contains(testing::ExpectInputError([&] { AllanNoiseForKalibr(a, cal, "allan.json"); }, a.dump()).what(),
                       "axes.y is missing"));
}

// RFC 4180 records: CRLF-terminated lines split with the project's splitter.
std::vector<std::vector<std::string>> ParseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = text.find("\r\n", start);
    EXPECT_NE(end, std::string::npos) << "a record not ended by CRLF";
    if (end == std::string::npos) break;
    std::vector<CsvField> fields;
    EXPECT_TRUE(SplitCsvLine(std::string_view(text).substr(start, end - start), &fields).message.empty());
    std::vector<std::string> row;
    for (const CsvField& f : fields) row.push_back(f.value);
    rows.push_back(row);
    start = end + 2;
  }
  return rows;
}

TEST(ExportCsv, MatchesGoldenText) {
  testing::ExpectMatchesGolden("calibration.csv", ExportCalibrationCsv(ExportTestCalibrationWithEffects()).text);
}

TEST(ExportCsv, ParsesBackToTheCalibration) {
  const Calibration cal = ExportTestCalibrationWithEffects();
  const auto rows = ParseCsv(ExportCalibrationCsv(cal).text);
  ASSERT_EQ(rows.size(), 1u + 9u + 10u + 2u);  // header, base, 3+3+3+1 effect parameters, 2 figures
  EXPECT_EQ(rows[0], (std::vector<std::string>{"name", "value", "sigma", "unit"}));
  const auto value = cal.model.ToVector(), sigma = cal.uncertainty.ToVector();
  for (int i = 0; i < kNumBaseParameters; ++i) {
    const auto& row = rows[static_cast<size_t>(i) + 1];
    ASSERT_EQ(row.size(), 4u);
    EXPECT_EQ(row[0], ParameterName(i));
    EXPECT_EQ(std::stod(row[1]), value(i));  // full round-trip precision
    EXPECT_EQ(std::stod(row[2]), sigma(i));
    EXPECT_EQ(row[3], ParameterUnit(i));
  }
  std::map<std::string, std::vector<std::string>> by_name;
  for (const auto& row : rows) by_name[row[0]] = row;
  EXPECT_EQ(std::stod(by_name.at("quadratic_nonlinearity.q_y")[1]), -0.015);
  EXPECT_EQ(std::stod(by_name.at("quadratic_nonlinearity.q_y")[2]), 0.002);
  EXPECT_EQ(by_name.at("temperature_bias.tc_bias_x")[2], "");  // no uncertainty given
  EXPECT_EQ(by_name.at("radius_offset.dr")[3], "m");
  EXPECT_EQ(std::stod(by_name.at("gravity_mps2")[1]), 9.80665);
}

TEST(ExportCsv, QuotesAsRfc4180Requires) {
  EXPECT_EQ(CsvQuote("counts"), "counts");
  EXPECT_EQ(CsvQuote("a,b"), "\"a,b\"");
  EXPECT_EQ(CsvQuote("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(CsvQuote("two\nlines"), "\"two\nlines\"");
}

}  // namespace
}  // namespace accelcal
