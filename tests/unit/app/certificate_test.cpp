// The calibration certificate (report/certificate.h): results rounded to their expanded
// uncertainty, the number stable across re-renders, the budget carried through the calibration
// file, the equipment read from the procedure's [equipment], and the diagnosis line's unit.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/virtual_bench.h"
#include "accelcal/app/calibration_pipeline.h"
#include "accelcal/app/report_inputs.h"
#include "accelcal/app/wizard/equipment_input.h"
#include "accelcal/base/error.h"
#include "accelcal/calibration/diagnosis/diagnosis.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/report/report_html.h"
#include "accelcal/report/report_model.h"
#include "accelcal/report/report_text.h"
#include "accelcal/report/svg_plot.h"
#include "accelcal/report/uncertainty_text.h"
#include "accelcal/session/session_journal.h"
#include "bench_calibration.h"

namespace accelcal::certificate_test {
namespace {

using testing::BenchInputs;
using testing::ProcedureWithEquipment;

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(RoundToUncertainty, TwoSignificantDigitsOfU) {
  const auto check = [](double v, double u, const std::string& value, const std::string& unc) {
    const RoundedResult r = RoundToUncertainty(v, u);
    EXPECT_EQ(r.value, value) << v << " +- " << u;
    EXPECT_EQ(r.uncertainty, unc) << v << " +- " << u;
  };
  check(2051.333812, 0.0441, "2051.334", "0.044");   // the example
  check(0.00135819, 4.4e-05, "0.001358", "0.000044");
  check(12345.6, 23.4, "12346", "23");
  check(1.23456, 0.0996, "1.23", "0.10");             // U rounds up to a new decade
  check(-0.00001, 0.5, "0.00", "0.50");               // no "-0.00"
  check(5.0, 0.0, "5", "-");                          // no U: six significant digits
}

TEST(Equipment, ReadFromTheProcedureInSiUnits) {
  const Procedure p = ProcedureWithEquipment(
      "[equipment.ruler]\nname = \"steel ruler\"\nid = \"RUL-7\"\nu_radius_mm = 0.5\n"
      "traceability = \"INTI length standard, cert. 123\"\n"
      "[equipment.turntable]\nid = \"TT-1\"\nu_speed_percent = 0.2\n"
      "[equipment.level]\nu_tilt_deg = 0.05\n");
  ASSERT_EQ(p.equipment.size(), 3u);
  const EquipmentItem* ruler = FindEquipment(p.equipment, EquipmentRole::kRuler);
  ASSERT_NE(ruler, nullptr);
  EXPECT_EQ(ruler->identification, "RUL-7");
  EXPECT_DOUBLE_EQ(ruler->standard_uncertainty, 0.0005);
  EXPECT_EQ(DescribeUncertainty(*ruler), "0.5 mm");
  const ReferenceUncertainties u = ToReferenceUncertainties(p.equipment, 0.0003);
  EXPECT_DOUBLE_EQ(u.gravity_mps2, 0.0003);
  EXPECT_DOUBLE_EQ(u.rpm_relative, 0.002);
  EXPECT_NEAR(u.table_tilt_rad, 0.05 * 3.14159265358979 / 180.0, 1e-12);
  EXPECT_TRUE(std::isnan(u.prism_squareness_rad));  // no prism listed
  // A typo in a role or a key, or a negative uncertainty, is refused naming it.
  EXPECT_THROW(ProcedureWithEquipment("[equipment.rulr]\nu_radius_mm = 0.5\n"), InputError);
  EXPECT_THROW(ProcedureWithEquipment("[equipment.ruler]\nu_radius_m = 0.5\n"), InputError);
  try {
    ProcedureWithEquipment("[equipment.prism]\nu_squareness_deg = -1\n");
    FAIL() << "a negative uncertainty was accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "u_squareness_deg")) << e.what();
  }
}

TEST(Equipment, TheFullProcedureListsTheBench) {
  const Procedure p = LoadProcedure(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/full_calibration.toml");
  EXPECT_EQ(p.equipment.size(), 4u);
  for (const EquipmentItem& e : p.equipment) {
    EXPECT_TRUE(std::isfinite(e.standard_uncertainty)) << InfoOf(e.role).key;
    EXPECT_FALSE(e.identification.empty()) << InfoOf(e.role).key;
  }
}

std::vector<EquipmentItem> Bench() {
  return ProcedureWithEquipment(
             "[equipment.ruler]\nname = \"steel ruler\"\nid = \"RUL-7\"\nu_radius_mm = 0.5\n"
             "traceability = \"INTI-cert-4711\"\n"
             "[equipment.turntable]\nid = \"TT-1\"\nu_speed_percent = 0.2\n"
             "[equipment.level]\nid = \"LVL-2\"\nu_tilt_deg = 0.05\n"
             "[equipment.prism]\nid = \"PR-1\"\nu_squareness_deg = 0.1\n")
      .equipment;
}

TEST(Certificate, BudgetTravelsThroughTheCalibrationFileAndTheNumberIsStable) {
  const ReportInputs in = BenchInputs(Bench());
  ASSERT_TRUE(in.calibration.budget.has_value());
  ASSERT_EQ(in.calibration.budget->parameters.size(), 9u);
  // The gravity's u came from the gravity question.
  EXPECT_DOUBLE_EQ(in.calibration.budget->parameters[0].contributions[1].standard_uncertainty, 0.0002);
  // Read back from its file form (what `accelcal report SESSION` does): the same budget and
  // the same certificate number.
  ReportInputs again = in;
  again.calibration = CalibrationFromJsonText(CalibrationToJsonText(in.calibration), "cal.json");
  ASSERT_TRUE(again.calibration.budget.has_value());
  for (size_t i = 0; i < 9; ++i) {
    const ParameterBudget& a = in.calibration.budget->parameters[i];
    const ParameterBudget& b = again.calibration.budget->parameters[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_DOUBLE_EQ(a.expanded, b.expanded);
    EXPECT_EQ(a.effective_dof, b.effective_dof);  // infinity survives JSON's null
    ASSERT_EQ(a.contributions.size(), b.contributions.size());
  }
  const ReportModel m1 = BuildReportModel(in), m2 = BuildReportModel(again);
  EXPECT_EQ(m1.certificate.number, m2.certificate.number);
  EXPECT_EQ(RenderReportText(m1), RenderReportText(m2));
  // Another session, another number.
  ReportInputs other = in;
  other.meta.session_name = "20261123T211201Z";
  EXPECT_NE(BuildReportModel(other).certificate.number, m1.certificate.number);
  EXPECT_EQ(m1.certificate.number.rfind("ACC-20261123T211200Z-", 0), 0u) << m1.certificate.number;
}

TEST(Certificate, TextAndHtmlStateWhatALabSigns) {
  ReportInputs in = BenchInputs(Bench());
  in.limits = LoadProcedure(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/full_calibration.toml").limits;
  const ReportModel m = BuildReportModel(in);
  const std::string text = RenderReportText(m), html = RenderReportHtml(m);
  for (const std::string& doc : {text, html}) {
    EXPECT_TRUE(Contains(doc, m.certificate.number));
    EXPECT_TRUE(Contains(doc, "SIMULATED"));
    EXPECT_TRUE(Contains(doc, "RUL-7"));
    EXPECT_TRUE(Contains(doc, "INTI-cert-4711"));
    EXPECT_TRUE(Contains(doc, "guard band"));  // the shipped procedure's rule
    EXPECT_TRUE(Contains(doc, "4.2.2"));
    EXPECT_TRUE(Contains(doc, "mrad"));
    EXPECT_TRUE(Contains(doc, " mg"));
    EXPECT_TRUE(Contains(doc, "counts/g"));
    EXPECT_TRUE(Contains(doc, "prism squareness"));
  }
  EXPECT_TRUE(Contains(html, "counter(pages)"));
  // Each result is rounded to its U: the bias's value has as many decimals as its U.
  const ParameterBudget& bx = *m.budget->Find(kBiasX);
  const RoundedResult r = RoundToUncertainty(bx.value, bx.expanded);
  EXPECT_TRUE(Contains(text, r.value + " +- " + r.uncertainty + " counts")) << text;
  for (const std::string& line : {std::string("offset x:"), std::string("misalignment a_yz:")})
    EXPECT_TRUE(Contains(text, line)) << line;
  // A real bench is not marked.
  ReportInputs real = BenchInputs(Bench());
  real.meta.source = "serial:/dev/ttyUSB0";
  const ReportModel mr = BuildReportModel(real);
  EXPECT_FALSE(Contains(RenderReportText(mr), "SIMULATED"));
  EXPECT_FALSE(Contains(RenderReportHtml(mr), "SIMULATED"));
}

TEST(Certificate, TheWelcomesEquipmentAnswerIsReadBackFromTheSession) {
  // `accelcal report SESSION` reads the welcome's answer from the journal (whose Inputs() is a
  // copy: reading it through a dangling iterator crashed the report command once).
  const std::unique_ptr<SessionJournal> journal = MakeMemoryJournal();
  journal->RecordInput("welcome", "device", "SN1");
  journal->RecordInput("welcome", "equipment", "ruler id RUL-77 u 0.4");
  journal->RecordResult(CalibrationToJsonText(BenchInputs(Bench()).calibration));
  ReportInputs in = ReportInputsFromJournal(*journal, "mem");
  EXPECT_EQ(in.equipment_answer, "ruler id RUL-77 u 0.4");
  const EquipmentAnswer edited = ApplyEquipmentAnswer(in.equipment_answer, Bench());
  ASSERT_TRUE(edited.ok()) << edited.error;
  const EquipmentItem* ruler = FindEquipment(edited.items, EquipmentRole::kRuler);
  ASSERT_NE(ruler, nullptr);
  EXPECT_EQ(ruler->identification, "RUL-77");
  EXPECT_DOUBLE_EQ(ruler->standard_uncertainty, 0.0004);
  EXPECT_EQ(ApplyEquipmentAnswer("keep", Bench()).items.size(), 4u);
  EXPECT_FALSE(ApplyEquipmentAnswer("hammer id 3", Bench()).ok());
  EXPECT_FALSE(ApplyEquipmentAnswer("ruler u -1", Bench()).ok());
  EXPECT_FALSE(ApplyEquipmentAnswer("ruler", Bench()).ok());
}

TEST(Certificate, WithoutEquipmentTheBudgetNamesWhatIsNotStated) {
  const ReportModel m = BuildReportModel(BenchInputs({}));
  ASSERT_TRUE(m.budget.has_value());
  EXPECT_EQ(m.certificate.not_stated, (std::vector<std::string>{"radius", "turntable speed", "table tilt"}));
  EXPECT_TRUE(Contains(RenderReportText(m), "Not stated (not in U): radius, turntable speed, table tilt"));
}

TEST(DiagnosisText, ADimensionlessParameterHasNoStrayUnit) {
  DiagnosisReport report;
  AdoptedEffect a;
  a.name = "rpm_scale";
  a.parameter_names = {"rpm_scale"};
  a.parameter_units = {"1"};
  a.parameters = {0.00135819};
  a.uncertainty = {4.4e-05};
  report.adopted.push_back(a);
  const std::string text = FormatDiagnosis(report);
  const size_t at = text.find("4.4e-05");
  ASSERT_NE(at, std::string::npos) << text;
  const std::string rest = text.substr(at, text.find('\n', at) - at);
  EXPECT_EQ(rest.find_last_not_of(' '), std::string("4.4e-05").size() - 1) << "'" << rest << "'";
}

TEST(SvgPlot, CoincidentPointsAreSpreadSoEachShows) {
  // Nine static poses at g and a lone turntable run: the nine set apart, centred where they were.
  std::vector<double> x(9, 9.80665);
  x.push_back(12.5);
  EXPECT_EQ(SpreadCoincident(&x, 0.1), 9);
  std::vector<double> nine(x.begin(), x.begin() + 9);
  std::sort(nine.begin(), nine.end());
  for (size_t i = 1; i < nine.size(); ++i) EXPECT_NEAR(nine[i] - nine[i - 1], 0.1, 1e-12);
  double mean = 0.0;
  for (double v : nine) mean += v / 9.0;
  EXPECT_NEAR(mean, 9.80665, 1e-12);
  EXPECT_DOUBLE_EQ(x.back(), 12.5);
  std::vector<double> apart = {1.0, 2.0, 3.0};
  EXPECT_EQ(SpreadCoincident(&apart, 0.1), 0);
  EXPECT_EQ(apart, (std::vector<double>{1.0, 2.0, 3.0}));
}

}  // namespace
}  // namespace accelcal::certificate_test
