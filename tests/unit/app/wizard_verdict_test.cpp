// The wizard's verdict is the certificate's (issue 27): the final summary shows the values with
// the U the certificate prints (the fit's 1-sigma in the details), and a required run the fit
// leaves out makes the session INCOMPLETE, named by its radius, never "Every step ... done".
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/io/calibration_file.h"
#include "accelcal/io/scenario_file.h"
#include "accelcal/io/session_result_file.h"
#include "accelcal/report/report_model.h"
#include "accelcal/report/report_text.h"
#include "accelcal/report/uncertainty_text.h"
#include "test_support.h"
#include "wizard_test_support.h"

namespace accelcal {
namespace {

using testing::Contains;

// The default bench, but asked for +y radial at 0.10 m the technician mounts the sensor at
// 0.106 m once: inside the live check's 10 %, out of the fit's agreement.
sim::Scenario MountedSixMillimetresOut() {
  sim::Scenario s = sim::LoadScenario(std::string(ACCELCAL_SOURCE_DIR) + "/scenarios/clumsy_wrong_radius.toml");
  EXPECT_EQ(s.technician.mistakes.size(), 1u);
  s.technician.mistakes.at(0).radius_m = 0.106;
  return s;
}

std::string Joined(const std::vector<std::string>& lines) {
  std::string all;
  for (const std::string& l : lines) all += l + "\n";
  return all;
}

// Reproduces item 2: the run was left out by the fit ("it disagrees with the other captures")
// and the certificate said "Overall: PASS" and "Every step of the procedure was done."
TEST(WizardVerdict, ARequiredRunLeftOutByTheFitIsIncompleteAndNamedByItsRadius) {
  testing::WizardRig rig(testing::ShortSeedProcedure(), MountedSixMillimetresOut());
  testing::AcceptUntil(rig.engine, testing::Never);
  const WizardView v = rig.engine.View();
  ASSERT_TRUE(v.finished);
  EXPECT_EQ(v.verdict, "INCOMPLETE") << Joined(v.lines);
  const std::string summary = Joined(v.lines);
  EXPECT_TRUE(Contains(summary, "incomplete: required step '+y radial, +z up at 100 mm, 120 rpm' its capture"))
      << summary;
  EXPECT_TRUE(Contains(summary, "was left out by the fit: disagrees with the other captures")) << summary;
  // The session's result carries it: `accelcal report` says the same.
  ReportInputs in;
  in.calibration = CalibrationFromJsonText(*rig.journal->Result(), "session");
  ReadAnalysesFromResultText(*rig.journal->Result(), "session", &in);
  ASSERT_TRUE(in.gaps.has_value());
  ASSERT_EQ(in.gaps->steps.size(), 1u);
  EXPECT_EQ(in.gaps->steps[0].id, "tt_y_100");
  const Procedure seed = testing::SeedProcedure();
  in.limits = seed.limits;
  in.nominal_bias_counts = seed.nominal.bias_counts;
  in.nominal_scale_counts_per_mps2 = seed.nominal.scale_counts_per_mps2;
  const std::string text = RenderReportText(BuildReportModel(in));
  EXPECT_FALSE(Contains(text, "Every step of the procedure was done")) << text;
  EXPECT_TRUE(Contains(text, "Result:             INCOMPLETE")) << text;
}

TEST(WizardVerdict, TheFinalSummaryShowsTheCertificatesU) {
  testing::WizardRig rig(testing::ShortSeedProcedure(), sim::DefaultScenario());
  testing::AcceptUntil(rig.engine, testing::Never);
  const WizardView v = rig.engine.View();
  ASSERT_EQ(v.verdict, "PASS") << Joined(v.lines);
  const std::string summary = Joined(v.lines);
  EXPECT_TRUE(Contains(summary, "Values +- U (k = 2, about 95 %), as on the certificate:")) << summary;
  // Each value with its U as the certificate rounds it (the budget's U, not the fit's 1-sigma).
  const Calibration cal = CalibrationFromJsonText(*rig.journal->Result(), "session");
  ASSERT_TRUE(cal.budget.has_value());
  const ParameterBudget& sy = *cal.budget->Find(kScaleY);
  const RoundedResult r = RoundToUncertainty(sy.value, sy.expanded);
  EXPECT_TRUE(Contains(summary, "y " + r.value + " +- " + r.uncertainty)) << summary;
  const ParameterBudget& zy = *cal.budget->Find(kMisZY);
  const RoundedResult m = RoundToUncertainty(zy.value * 1e3, zy.expanded * 1e3);
  EXPECT_TRUE(Contains(summary, "zy " + m.value + " +- " + m.uncertainty)) << summary;
  for (const std::string& l : v.lines) EXPECT_LE(l.size(), 80u) << l;
}

}  // namespace
}  // namespace accelcal
