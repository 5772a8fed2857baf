// Issue 17: a bounded random-mutation test of the readers of outside files (capture set,
// recording, calibration, procedure). Each starts from a valid file and parses thousands of
// mutants (bytes flipped, inserted, deleted, repeated, cut; hostile tokens such as 1e999, NUL,
// ill-formed UTF-8, a lone quote). A reader may accept a mutant or refuse it with an
// accelcal::Error; any other exception (a library's, std::out_of_range...) fails, and so does a
// calibration accepted with outputs that cannot be finite. The sanitizer build runs the same
// test, which is where a crash or an out-of-bounds read would show.
//
// Bounded for CI (ACCELCAL_FUZZ_ITERATIONS mutants per reader, default 1500: well under a second
// each in the normal build); the seed is fixed so a failure reproduces, and printed.
#include <cstdlib>
#include <exception>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/calibration/apply.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/io/capture_set_reader.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/io/recording_reader.h"
#include "export_test_support.h"

namespace accelcal {
namespace {

int Iterations() {
  const char* v = std::getenv("ACCELCAL_FUZZ_ITERATIONS");
  return v ? std::max(1, std::atoi(v)) : 1500;
}

const std::vector<std::string> kTokens = {
    "1e999", "-1e999", "nan", "inf", "-0", "1e-320", "99999999999999999999999", "\xFF", "\xC3", "\xE2\x80\xA8",
    std::string(1, '\0'), "\"", ",", "\n", "\r\n", "#", "[", "]", "{", "}", ":", "=", "'", "\\", "\t",
    "null", "true", "[[", "\"\"\"", "0x10", "+", "-", "e", ".", "capture", "turntable", "static"};

// One mutation of `text`, chosen by `rng`.
std::string Mutate(std::string text, std::mt19937& rng) {
  auto pick = [&](size_t n) { return n == 0 ? size_t{0} : std::uniform_int_distribution<size_t>(0, n - 1)(rng); };
  const int rounds = 1 + static_cast<int>(pick(4));
  for (int r = 0; r < rounds; ++r) {
    const size_t at = pick(text.size() + 1);
    switch (pick(6)) {
      case 0:  // flip bits of a byte
        if (!text.empty()) text[at % text.size()] ^= static_cast<char>(1 + pick(255));
        break;
      case 1:  // insert a random byte
        text.insert(at, 1, static_cast<char>(pick(256)));
        break;
      case 2:  // delete a range
        text.erase(at, pick(40));
        break;
      case 3:  // repeat a range
        text.insert(at, text.substr(pick(text.size() + 1), pick(200)));
        break;
      case 4:  // a hostile token
        text.insert(at, kTokens[pick(kTokens.size())]);
        break;
      default:  // cut
        text.resize(at);
        break;
    }
  }
  return text;
}

// Runs `read` on mutants of `seed`; fails on any exception that is not an accelcal::Error.
void Fuzz(const std::string& name, const std::string& seed, const std::function<void(const std::string&)>& read,
          unsigned rng_seed) {
  ASSERT_NO_THROW(read(seed)) << name << ": the seed itself is refused";
  std::mt19937 rng(rng_seed);
  int refused = 0;
  const int n = Iterations();
  for (int i = 0; i < n; ++i) {
    const std::string mutant = Mutate(seed, rng);
    try {
      read(mutant);
    } catch (const Error&) {
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << name << " mutant " << i << " (rng seed " << rng_seed << "): not an accelcal::Error: "
                    << e.what();
      return;
    }
  }
  // A mutation test whose mutants are all refused (or all accepted) tests too little.
  EXPECT_GT(refused, 0) << name;
  EXPECT_LT(refused, n) << name;
}

std::string CaptureSetSeed() {
  std::string t = "# adc_range_counts = 0,4095\ncapture,kind,t,ax,ay,az,temp_c,radius_m,rpm,label,up_axis\n";
  for (int k = 0; k < 6; ++k) t += "1,static," + std::to_string(k * 0.01) + ",2053,2043,2399,25,,,\"z up, granite\",\n";
  for (int k = 0; k < 6; ++k) t += "2,turntable," + std::to_string(1 + k * 0.01) + ",2040,2790,2930,,0.15,60,spin,+z\n";
  return t;
}

std::string RecordingSeed() {
  std::string t = "# accelcal recording\n";
  for (int k = 0; k < 12; ++k) t += std::to_string(k * 0.01) + " 2051 2043.5 2399 24.5\n";
  return t;
}

std::string FileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ReaderFuzz, CaptureSet) {
  Fuzz("capture set", CaptureSetSeed(), [](const std::string& t) { ParseCaptureSet(t, "set.csv"); }, 17);
}

TEST(ReaderFuzz, Recording) {
  Fuzz("recording", RecordingSeed(), [](const std::string& t) { ParseRecording(t, "rec.txt"); }, 18);
}

TEST(ReaderFuzz, Calibration) {
  const std::string seed = CalibrationToJsonText(testing::ExportTestCalibrationWithEffects());
  Fuzz("calibration", seed,
       [](const std::string& t) {
         const Calibration cal = CalibrationFromJsonText(t, "cal.json");
         // Accepted: its base model gives a finite output for any 32-bit reading.
         if (!cal.model.Validate().empty()) throw std::logic_error("accepted an invalid model: " + cal.model.Validate());
         if (!cal.model.Calibrate(Eigen::Vector3d(2048, 2048, 2048)).allFinite())
           throw std::logic_error("accepted a model with a non-finite output");
       },
       19);
}

// The full procedure as the io layer alone reads it: its closing repeat pose is of a kind the
// wizard defines (registered from app up, step_registry.h), so the seed leaves that step out.
std::string ProcedureSeed() {
  std::string text = FileText(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/full_calibration.toml");
  const size_t from = text.find("[[step]]\nid = \"repeat_pz\"");
  const size_t to = from == std::string::npos ? from : text.find("[[step]]", from + 1);
  if (to != std::string::npos) text.erase(from, to - from);
  return text;
}

TEST(ReaderFuzz, Procedure) {
  const std::string seed = ProcedureSeed();
  ASSERT_FALSE(seed.empty());
  Fuzz("procedure", seed, [](const std::string& t) { ParseProcedure(t, "procedure.toml"); }, 20);
}

}  // namespace
}  // namespace accelcal

namespace accelcal {
namespace {

// What the procedure fuzz found first: a turntable step whose up_axis is the default radial
// axis (+x), with no "radial" key, dereferenced the missing key's node (a crash).
TEST(ReaderFuzz, ProcedureDefaultRadialAlongUpAxisIsAnError) {
  std::string text = FileText(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/full_calibration.toml");
  const size_t at = text.find("radial = \"+x\"\nup_axis = \"+z\"");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, std::string("radial = \"+x\"\nup_axis = \"+z\"").size(), "up_axis = \"+x\"");
  try {
    ParseProcedure(text, "procedure.toml");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("radial: must be perpendicular to up_axis"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace accelcal
