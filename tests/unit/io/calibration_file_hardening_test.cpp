// Issue 17, items 7 and 11: a calibration file whose numbers cannot give finite outputs, or
// hold a literal beyond a double (1e999), is refused naming the file and the place, never with
// a library's exception text; text that is not UTF-8 never stops a JSON output.
#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/base/safe_text.h"
#include "accelcal/io/calibration_file.h"
#include "export_test_support.h"

namespace accelcal {
namespace {

std::string Refusal(const std::string& text) {
  try {
    CalibrationFromJsonText(text, "cal.json");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return {};
}

TEST(CalibrationFileHardening, NumberBeyondADoubleNamesItsPlace) {
  std::string text = CalibrationToJsonText(testing::ExportTestCalibration());
  const size_t at = text.find("\"bias_counts\": [\n    ") + 21;
  text.replace(at, text.find(',', at) - at, "1e999");
  const std::string why = Refusal(text);
  EXPECT_NE(why.find("cal.json:3:5"), std::string::npos) << why;
  EXPECT_NE(why.find("1e999 is beyond a double's range"), std::string::npos) << why;
  EXPECT_EQ(why.find("json.exception"), std::string::npos) << why;
}

TEST(CalibrationFileHardening, ScaleThatMakesOutputsInfiniteIsRefused) {
  for (double scale : {1e-320, 1e-300}) {
    Calibration cal = testing::ExportTestCalibration();
    cal.model.scale_counts_per_mps2.y() = scale;
    const std::string why = Refusal(CalibrationToJsonText(cal));
    EXPECT_NE(why.find("would calibrate to an infinite value"), std::string::npos) << scale << ": " << why;
  }
  Calibration huge_misalignment = testing::ExportTestCalibration();
  huge_misalignment.model.a_zy_rad = 1e306;
  EXPECT_NE(Refusal(CalibrationToJsonText(huge_misalignment)).find("infinite value"), std::string::npos);
  // A weak but real sensor (1 count per m/s^2) is not refused.
  Calibration weak = testing::ExportTestCalibration();
  weak.model.scale_counts_per_mps2.z() = 1.0;
  EXPECT_NO_THROW(CalibrationFromJsonText(CalibrationToJsonText(weak), "cal.json"));
}

TEST(CalibrationFileHardening, IllFormedUtf8IsWrittenAsReplacementCharacters) {
  Calibration cal = testing::ExportTestCalibration();
  cal.source = "captures-Se\xF1or.csv";  // a Latin-1 file name
  if (!cal.captures.empty()) cal.captures.front().label = "z up \xFF";
  std::string text;
  ASSERT_NO_THROW(text = CalibrationToJsonText(cal));
  EXPECT_TRUE(IsValidUtf8(text));
  EXPECT_NE(text.find("captures-Se\xEF\xBF\xBDor.csv"), std::string::npos) << text;
  EXPECT_NO_THROW(CalibrationFromJsonText(text, "cal.json"));
}

}  // namespace
}  // namespace accelcal
