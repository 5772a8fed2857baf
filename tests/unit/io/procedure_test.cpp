// The shipped procedures load; malformed ones are refused with file, line and what is wrong.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/session/procedure.h"

namespace accelcal::procedure_test {
namespace {

std::string Shipped(const std::string& name) {
  return std::string(ACCELCAL_SOURCE_DIR) + "/procedures/" + name;
}

// FullCalibrationLoads is in the app group (tests/unit/app/wizard_repeat_step_test.cpp): the full
// procedure has a step of a kind the wizard defines (repeat), registered from app up.

TEST(ProcedureTest, NoiseAndDriftRecordsLoad) {
  const Procedure noise = LoadProcedure(Shipped("noise.toml"));
  ASSERT_EQ(noise.steps.size(), 2u);
  EXPECT_EQ(noise.steps[0].kind, StepKind::kRecord);
  EXPECT_EQ(noise.steps[1].kind, StepKind::kAnalysis);
  EXPECT_EQ(noise.steps[1].record_step, "noise");
  EXPECT_EQ(noise.steps[1].method, "noise");
  EXPECT_DOUBLE_EQ(noise.steps[0].duration_s, 60.0);
  EXPECT_GT(noise.steps[0].timeout_s, 60.0);
  const Procedure drift = LoadProcedure(Shipped("drift.toml"));
  ASSERT_EQ(drift.steps.size(), 2u);
  EXPECT_EQ(drift.steps[1].kind, StepKind::kAnalysis);
  EXPECT_EQ(drift.steps[1].record_step, "drift");
  EXPECT_EQ(drift.steps[1].method, "allan");
  EXPECT_DOUBLE_EQ(drift.steps[0].duration_s, 12 * 3600.0);
  EXPECT_GT(drift.steps[0].timeout_s, drift.steps[0].duration_s);
  EXPECT_DOUBLE_EQ(drift.steps[0].chunk_s, 10.0);
  EXPECT_DOUBLE_EQ(noise.steps[0].chunk_s, ProcedureStep::kDefaultRecordChunkS);
}

const char* kHead = "title = \"t\"\n[sensor]\nnominal_scale_counts_per_mps2 = 34.8\n"
                    "nominal_bias_counts = 2048\n";

// The InputError of parsing `text`, as "line: message".
std::string Refusal(const std::string& text) {
  try {
    ParseProcedure(text, "p.toml");
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "p.toml");
    return std::to_string(e.line()) + ": " + e.message();
  }
  return "accepted";
}

TEST(ProcedureTest, FormerTitlesAreAnArrayOfStrings) {
  const std::string sensor = "[sensor]\nnominal_scale_counts_per_mps2 = 34.8\nnominal_bias_counts = 2048\n"
                             "[[step]]\nid = \"a\"\nkind = \"static\"\nup = [0, 0, 1]\n";
  const Procedure p = ParseProcedure("title = \"new\"\nformer_titles = [\"old\", \"older\"]\n" + sensor, "p.toml");
  EXPECT_EQ(p.former_titles, (std::vector<std::string>{"old", "older"}));
  EXPECT_TRUE(p.IsTitled("older"));
  EXPECT_TRUE(ParseProcedure("title = \"t\"\n" + sensor, "p.toml").former_titles.empty());
  EXPECT_NE(Refusal("title = \"t\"\nformer_titles = \"old\"\n" + sensor).find("2: "), std::string::npos);
  EXPECT_NE(Refusal("title = \"t\"\nformer_titles = [1]\n" + sensor).find("must be an array of strings"),
            std::string::npos);
}

TEST(ProcedureTest, MalformedProceduresAreRefusedWithLineAndReason) {
  const std::string head = kHead;  // 4 lines
  EXPECT_EQ(Refusal(head + "[[step]]\nid = \"a\"\nkind = \"static\"\nupp = [0, 0, 1]\n"),
            "8: unknown key 'step 1.upp' (misspelt?)");
  EXPECT_NE(Refusal(head + "[[step]]\nid = \"a\"\nkind = \"dance\"\n").find("7: step 1.kind: 'dance'"),
            std::string::npos);
  EXPECT_EQ(Refusal(head + "[[step]]\nid = \"a\"\nkind = \"static\"\nup = [0, 0]\n").rfind("8: step 1.up", 0), 0u);
  EXPECT_EQ(Refusal(head + "[[step]]\nid = \"a\"\nkind = \"turntable\"\nradius_m = -1\nrpm = 120\n")
                .rfind("8: step 1.radius_m", 0), 0u);
  EXPECT_EQ(Refusal(head + "[[step]]\nid = \"a\"\nkind = \"fit\"\n[[step]]\nid = \"a\"\nkind = \"report\"\n")
                .rfind("9: step 2.id: 'a' is used twice", 0), 0u);
  EXPECT_EQ(Refusal(head + "[[step]]\nid = \"a\"\nkind = \"turntable\"\nradius_m = 0.1\nrpm = 120\n"
                    "radial = \"+z\"\nup_axis = \"-z\"\n").rfind("10: step 1.radial", 0), 0u);
  EXPECT_EQ(Refusal(head + "[[step]]\nid = \"a\"\nkind = \"static\"\nduration_s = 20\ntimeout_s = 10\n")
                .rfind("9: step 1.timeout_s", 0), 0u);
  EXPECT_EQ(Refusal(head + "[[step]]\nid = \"a\"\nkind = \"record\"\nchunk_s = 0\n")
                .rfind("8: step 1.chunk_s", 0), 0u);
  // An analysis names an earlier record step and a known method.
  EXPECT_EQ(Refusal(head + "[[step]]\nid = \"n\"\nkind = \"analysis\"\nrecord = \"r\"\nmethod = \"allan\"\n")
                .rfind("8: step 1.record: 'r' is not an earlier record step", 0), 0u);
  EXPECT_EQ(Refusal(head + "[[step]]\nid = \"r\"\nkind = \"record\"\n[[step]]\nid = \"n\"\n"
                    "kind = \"analysis\"\nrecord = \"r\"\nmethod = \"fft\"\n")
                .rfind("12: step 2.method: 'fft' is not an analysis", 0), 0u);
  // chunk_s belongs to records only.
  EXPECT_EQ(Refusal(head + "[[step]]\nid = \"a\"\nkind = \"static\"\nchunk_s = 5\n"),
            "8: unknown key 'step 1.chunk_s' (misspelt?)");
  EXPECT_NE(Refusal("title = \"t\"\n[[step]]\nid = \"a\"\nkind = \"fit\"\n").find("[sensor]"),
            std::string::npos);
  EXPECT_EQ(Refusal("title = \"t\n").rfind("1: ", 0), 0u);
  EXPECT_NE(Refusal(head).find("no [[step]]"), std::string::npos);
}

TEST(ProcedureTest, MissingFileIsAnError) {
  EXPECT_THROW(LoadProcedure("/nonexistent/procedure.toml"), Error);
}

}  // namespace
}  // namespace accelcal::procedure_test
