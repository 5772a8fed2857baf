#include "accelcal/io/calibration_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/session_result_file.h"

namespace accelcal {
namespace {

using nlohmann::json;

Calibration Example() {
  Calibration cal;
  cal.model.bias_counts = {2048.125, 2040.5, 2060.25};
  cal.model.scale_counts_per_mps2 = {34.6 + 1e-13, 35.07, 34.41};
  cal.model.a_yz_rad = 0.004259123456789;
  cal.model.a_zy_rad = -0.00282;
  cal.model.a_zx_rad = 0.005656;
  cal.uncertainty.bias_counts = {0.02, 0.03, 0.025};
  cal.uncertainty.scale_counts_per_mps2 = {0.002, 0.003, 0.0025};
  cal.gravity = GravitySpec::Given(9.81744);
  cal.residual_rms_mps2 = 0.001;
  CalibrationCapture r;
  r.id = 7;
  r.label = "z up, \"prism\"";
  r.n_samples = 1000;
  r.residual_mps2 = 0.0004;
  cal.captures.push_back(r);
  return cal;
}

std::string Expect(const json& j) {
  try {
    CalibrationFromJson(j, "cal.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CalibrationFile, JsonHasTheDocumentedFields) {
  const json j = CalibrationToJson(Example());
  EXPECT_EQ(j["format"], "accelcal-calibration/1");
  for (const char* key : {"gravity_mps2", "bias_counts", "scale_counts_per_mps2", "misalignment_rad",
                          "uncertainty", "residual_rms_mps2", "effects", "captures", "gravity_source"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_TRUE(j["effects"].is_array());
  EXPECT_EQ(j["gravity_source"]["source"], "given");
  const json& c = j["captures"][0];
  for (const char* key : {"id", "kind", "label", "used", "reason", "n_samples", "residual_mps2"})
    EXPECT_TRUE(c.contains(key)) << key;
  EXPECT_TRUE(c["reason"].is_null());
  EXPECT_TRUE(c["radius_m"].is_null());  // NaN is written as null, never as invalid JSON
}

TEST(CalibrationFile, FileRoundTripIsExact) {
  const std::string path = ::testing::TempDir() + "/accelcal_cal_roundtrip.json";
  WriteCalibrationFile(path, Example());
  const Calibration back = ReadCalibrationFile(path);
  EXPECT_EQ(back.model.ToVector(), Example().model.ToVector());
  EXPECT_EQ(back.captures[0].label, Example().captures[0].label);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  std::filesystem::remove(path);
}

TEST(CalibrationFile, GravityAndItsUncertaintyRoundTrip) {
  for (const GravitySpec& g : {GravitySpec::Given(9.7803, 0.00002), GravitySpec::Standard(),
                               GravitySpec::FromLocation(-34.9, 43.0)}) {
    Calibration cal = Example();
    cal.gravity = g;
    const Calibration back = CalibrationFromJson(CalibrationToJson(cal), "cal.json");
    EXPECT_EQ(back.gravity.source, g.source);
    EXPECT_DOUBLE_EQ(back.gravity.gravity_mps2, g.gravity_mps2);
    EXPECT_DOUBLE_EQ(back.gravity.sigma_mps2, g.sigma_mps2);
    EXPECT_DOUBLE_EQ(back.gravity.latitude_deg, g.latitude_deg);
  }
  // A file written before the uncertainty was recorded: the source's own, or "not stated".
  json j = CalibrationToJson(Example());
  j["gravity_source"].erase("sigma_mps2");
  EXPECT_TRUE(std::isnan(CalibrationFromJson(j, "cal.json").gravity.sigma_mps2));
  j["gravity_source"]["source"] = "standard";
  EXPECT_NEAR(CalibrationFromJson(j, "cal.json").gravity.sigma_mps2, kStandardGravitySigmaMps2, 1e-15);
  j["gravity_source"]["sigma_mps2"] = "big";
  EXPECT_NE(Expect(j).find("gravity_source.sigma_mps2"), std::string::npos) << Expect(j);
}

// The reference pose's path (pose_repeats): each repeat against the first, read back as written;
// a file without it (written before) has none; a move that is not a number is refused.
TEST(CalibrationFile, PoseRepeatsRoundTrip) {
  Calibration cal = Example();
  EXPECT_FALSE(CalibrationToJson(cal).contains("pose_repeats"));
  PoseRepeat r;
  r.label = "+z up";
  r.first_id = 1;
  r.again_id = 13;
  r.elapsed_s = 512.5;
  r.moved_counts = -0.625;
  r.noise_counts = 0.0625;
  r.beyond_noise = true;
  cal.pose_repeats = {r, r};
  cal.pose_repeats[1].again_id = 21;
  cal.pose_repeats[1].beyond_noise = false;
  const Calibration back = CalibrationFromJson(CalibrationToJson(cal), "cal.json");
  ASSERT_EQ(back.pose_repeats.size(), 2u);
  EXPECT_EQ(back.pose_repeats[0].label, "+z up");
  EXPECT_EQ(back.pose_repeats[0].first_id, 1);
  EXPECT_EQ(back.pose_repeats[0].again_id, 13);
  EXPECT_DOUBLE_EQ(back.pose_repeats[0].elapsed_s, 512.5);
  EXPECT_DOUBLE_EQ(back.pose_repeats[0].moved_counts, -0.625);
  EXPECT_DOUBLE_EQ(back.pose_repeats[0].noise_counts, 0.0625);
  EXPECT_TRUE(back.pose_repeats[0].beyond_noise);
  EXPECT_EQ(back.pose_repeats[1].again_id, 21);
  EXPECT_FALSE(back.pose_repeats[1].beyond_noise);
  EXPECT_TRUE(CalibrationFromJson(CalibrationToJson(Example()), "cal.json").pose_repeats.empty());
  json j = CalibrationToJson(cal);
  j["pose_repeats"][1]["moved_counts"] = "far";
  EXPECT_NE(Expect(j).find("pose_repeats[1].moved_counts"), std::string::npos) << Expect(j);
}

TEST(CalibrationFile, ASessionResultCarriesItsGaps) {
  SessionGaps gaps;
  gaps.steps.push_back({"pose_mx", "-x up", "skipped", true});
  gaps.identification.push_back("operator");
  gaps.gravity_ambiguity = "rpm_scale found while gravity is the standard value";
  const std::string text = SessionResultJsonText(Example(), gaps);
  EXPECT_EQ(CalibrationFromJsonText(text, "r").model.ToVector(), Example().model.ToVector());
  ReportInputs in;
  ReadAnalysesFromResultText(text, "r", &in);
  ASSERT_TRUE(in.gaps.has_value());
  ASSERT_EQ(in.gaps->steps.size(), 1u);
  EXPECT_EQ(in.gaps->steps[0].title, "-x up");
  EXPECT_TRUE(in.gaps->steps[0].required);
  EXPECT_EQ(in.gaps->identification, std::vector<std::string>{"operator"});
  EXPECT_EQ(in.gaps->gravity_ambiguity, "rpm_scale found while gravity is the standard value");
}

TEST(CalibrationFile, RefusesAnotherFormat) {
  json j = CalibrationToJson(Example());
  j["format"] = "accelcal-calibration/9";
  EXPECT_NE(Expect(j).find("field 'format'"), std::string::npos) << Expect(j);
}

TEST(CalibrationFile, RefusesMissingField) {
  json j = CalibrationToJson(Example());
  j.erase("scale_counts_per_mps2");
  EXPECT_NE(Expect(j).find("cal.json: field 'scale_counts_per_mps2': missing"), std::string::npos) << Expect(j);
}

TEST(CalibrationFile, RefusesWrongTypesAndNonFiniteValues) {
  json j = CalibrationToJson(Example());
  j["bias_counts"][1] = "2048";
  EXPECT_NE(Expect(j).find("field 'bias_counts[1]'"), std::string::npos) << Expect(j);
  j = CalibrationToJson(Example());
  j["bias_counts"] = json::array({1, 2});
  EXPECT_NE(Expect(j).find("array of 3 numbers"), std::string::npos) << Expect(j);
  j = CalibrationToJson(Example());
  j["misalignment_rad"]["zx"] = nullptr;
  EXPECT_NE(Expect(j).find("field 'misalignment_rad.zx'"), std::string::npos) << Expect(j);
  j = CalibrationToJson(Example());
  j["captures"][0]["kind"] = "spinning";
  EXPECT_NE(Expect(j).find("captures[0].kind"), std::string::npos) << Expect(j);
  j = CalibrationToJson(Example());
  j["effects"] = "none";
  EXPECT_NE(Expect(j).find("field 'effects'"), std::string::npos) << Expect(j);
}

TEST(CalibrationFile, RefusesANegativeScale) {
  json j = CalibrationToJson(Example());
  j["scale_counts_per_mps2"][2] = -34.0;
  EXPECT_NE(Expect(j).find("scale_z must be positive"), std::string::npos) << Expect(j);
}

TEST(CalibrationFile, TruncatedFileNamesWhere) {
  const std::string path = ::testing::TempDir() + "/accelcal_cal_truncated.json";
  const std::string text = CalibrationToJson(Example()).dump(2);
  std::ofstream(path) << text.substr(0, text.size() / 2);
  try {
    ReadCalibrationFile(path);
    FAIL() << "a truncated file was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_GT(e.line(), 1);
    EXPECT_NE(std::string(e.what()).find("not valid JSON"), std::string::npos);
  }
  std::filesystem::remove(path);
}

TEST(CalibrationFile, MissingFileIsAClearError) {
  try {
    ReadCalibrationFile("/nonexistent/cal.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open '/nonexistent/cal.json'"), std::string::npos);
  }
}

}  // namespace
}  // namespace accelcal
