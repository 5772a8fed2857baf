// Issue 17, item 12: what the reports show of an undefined statistic and of hostile labels.
#include <string>

#include <gtest/gtest.h>

#include "accelcal/report/report_model.h"
#include "accelcal/report/report_text.h"
#include "export_test_support.h"

namespace accelcal {
namespace {

TEST(ReportHardening, Chi2PerDofAtZeroDegreesOfFreedomIsNotANumberShown) {
  ReportInputs in;
  in.calibration = testing::ExportTestCalibration();
  in.calibration.fit.dof = 0;
  in.calibration.fit.chi2_per_dof = -1.0;  // what a fit with as many parameters as data writes
  const std::string text = RenderReportText(BuildReportModel(in));
  EXPECT_EQ(text.find("-1.000"), std::string::npos) << text;
  EXPECT_NE(text.find("chi2/dof:                           -\n"), std::string::npos) << text;
}

TEST(ReportHardening, ControlCharactersInLabelsAreEscaped) {
  ReportInputs in;
  in.calibration = testing::ExportTestCalibration();
  CalibrationCapture c;
  c.id = 1;
  c.label = "z\x1B[2J\rup\xC2\x85";
  c.n_samples = 10;
  in.calibration.captures.push_back(c);
  const std::string text = RenderReportText(BuildReportModel(in));
  for (char ch : text) EXPECT_FALSE(static_cast<unsigned char>(ch) < 0x20 && ch != '\n') << text;
  EXPECT_NE(text.find("z\\x1B[2J\\ru"), std::string::npos) << text;
}

}  // namespace
}  // namespace accelcal
