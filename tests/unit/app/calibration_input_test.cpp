// A calibration given to a command (app/calibration_input.h): the one rule that tells a
// calibration file from a session, the one set of errors, and the report's inputs gathered from
// either (app/report_metadata.h).
#include "accelcal/app/calibration_input.h"

#include <sys/stat.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "accelcal/app/report_metadata.h"
#include "accelcal/base/error.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/io/procedure_file.h"
#include "export_test_support.h"
#include "session_test_support.h"

namespace accelcal::calibration_input_test {
namespace {

namespace fs = std::filesystem;

// The message of the accelcal::Error `fn` throws; a test failure when it throws none.
template <typename Fn>
std::string ErrorOf(Fn&& fn) {
  try {
    fn();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

void WriteText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string FullProcedurePath() {
  return std::string(ACCELCAL_SOURCE_DIR) + "/procedures/full_calibration.toml";
}

class CalibrationInputTest : public testing::SessionDirTest {
 protected:
  // The session file path_ of `device`, which ran `procedure`; with the test calibration as its
  // result when `finished`.
  void MakeSession(bool finished, const std::string& procedure = "bench_default") {
    SessionOpenOptions o = Writer();
    o.procedure = procedure;
    auto store = SessionStore::Open(path_, o);
    store->RecordInput(kSessionStep, kDeviceKey, "SN-0042");
    if (finished) store->RecordResult(CalibrationToJsonText(testing::ExportTestCalibration()));
  }

  static Eigen::VectorXd Parameters(const Calibration& cal) { return cal.model.ToVector(); }
};

TEST_F(CalibrationInputTest, JsonFileIsACalibrationFile) {
  const fs::path file = dir_ / "cal.json";
  WriteText(file, "\n  " + CalibrationToJsonText(testing::ExportTestCalibration()));
  const LocatedCalibrationInput at = LocateCalibrationInput(file.string());
  EXPECT_EQ(at.kind, CalibrationInputKind::kCalibrationFile);
  EXPECT_EQ(at.path, file.string());
  const CalibrationInput in = ReadCalibrationInput(file.string());
  EXPECT_EQ(Parameters(in.calibration), Parameters(testing::ExportTestCalibration()));
  EXPECT_FALSE(in.session.has_value());
  EXPECT_FALSE(IsSessionFile(file.string()));
}

TEST_F(CalibrationInputTest, SessionFileIsASessionWithItsOrigin) {
  MakeSession(true);
  EXPECT_TRUE(IsSessionFile(path_));
  EXPECT_EQ(LocateCalibrationInput(path_).kind, CalibrationInputKind::kSession);
  const CalibrationInput in = ReadCalibrationInput(path_);
  EXPECT_EQ(in.kind, CalibrationInputKind::kSession);
  ASSERT_TRUE(in.session.has_value());
  EXPECT_EQ(in.session->device, "SN-0042");
  EXPECT_EQ(Parameters(in.calibration), Parameters(testing::ExportTestCalibration()));
}

TEST_F(CalibrationInputTest, SessionWithoutCalibrationSaysSo) {
  MakeSession(false);
  EXPECT_EQ(ErrorOf([&] { ReadCalibrationInput(path_); }),
            "session " + path_ + " has no calibration yet: 0 captures accepted; run the wizard to "
            "finish it");
  EXPECT_EQ(ErrorOf([&] { ReportInputsOf(path_); }),
            "session " + path_ + " has no calibration yet: 0 captures accepted; run the wizard to "
            "finish it");
}

TEST_F(CalibrationInputTest, FileThatIsNeitherIsRefusedByName) {
  const fs::path junk = dir_ / "junk.db";
  WriteText(junk, "not a database\n");
  const std::string why = ErrorOf([&] { LocateCalibrationInput(junk.string()); });
  EXPECT_NE(why.find(junk.string() + " is not an accelcal session or a calibration file"), std::string::npos)
      << why;
  WriteText(junk, "");
  EXPECT_NE(ErrorOf([&] { ReadCalibrationInput(junk.string()); }).find("is not an accelcal session"),
            std::string::npos);
}

TEST_F(CalibrationInputTest, MissingPathIsAMissingFile) {
  const std::string missing = (dir_ / "missing.json").string();
  EXPECT_EQ(ErrorOf([&] { ReadCalibrationInput(missing); }),
            "cannot open '" + missing + "': No such file or directory");
}

// A bare name is a session's name in the default session folder ($XDG_DATA_HOME's).
TEST_F(CalibrationInputTest, BareNameIsASessionInTheDefaultFolder) {
  const char* old = std::getenv("XDG_DATA_HOME");
  const std::string saved = old == nullptr ? "" : old;
  ::setenv("XDG_DATA_HOME", dir_.c_str(), 1);
  const fs::path folder = dir_ / "accelcal" / "sessions";
  fs::create_directories(folder);
  path_ = (folder / "bench1.db").string();
  MakeSession(true);
  const LocatedCalibrationInput at = LocateCalibrationInput("bench1");
  const std::string why = ErrorOf([] { LocateCalibrationInput("nosuch"); });
  if (old == nullptr) ::unsetenv("XDG_DATA_HOME");
  else ::setenv("XDG_DATA_HOME", saved.c_str(), 1);
  EXPECT_EQ(at.kind, CalibrationInputKind::kSession);
  EXPECT_EQ(at.path, path_);
  EXPECT_EQ(why.rfind("no session nosuch (looked in " + folder.string(), 0), 0u) << why;
}

// `refit`'s input: a session, opened for writing; a calibration file is refused by name (it has
// no captures to fit again), a file that is neither and a missing session as for every command.
TEST_F(CalibrationInputTest, SessionToChangeIsASessionOnly) {
  MakeSession(true);
  {
    const std::unique_ptr<SessionStore> store = OpenSessionToChange(path_);
    EXPECT_EQ(store->Info().device, "SN-0042");
    EXPECT_NO_THROW(store->RecordInput(kSessionStep, kDeviceKey, "SN-0043"));  // open for writing
  }
  const fs::path file = dir_ / "cal.json";
  WriteText(file, CalibrationToJsonText(testing::ExportTestCalibration()));
  const std::string why = ErrorOf([&] { OpenSessionToChange(file.string()); });
  EXPECT_EQ(why.rfind(file.string() + " is a calibration file, not a session", 0), 0u) << why;
  const fs::path junk = dir_ / "junk.db";
  WriteText(junk, "not a database\n");
  EXPECT_NE(ErrorOf([&] { OpenSessionToChange(junk.string()); }).find("is not an accelcal session"),
            std::string::npos);
  const std::string missing = (dir_ / "missing.db").string();
  EXPECT_EQ(ErrorOf([&] { OpenSessionToChange(missing); }), "no session " + missing);
}

// A pipe is never sniffed (the bytes read would be gone): it is a calibration file's text.
TEST_F(CalibrationInputTest, PipeIsReadOnceAsACalibrationFile) {
  const std::string fifo = (dir_ / "cal.fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_FALSE(IsSessionFile(fifo));
  EXPECT_EQ(LocateCalibrationInput(fifo).kind, CalibrationInputKind::kCalibrationFile);
  std::thread writer([&] { WriteText(fifo, CalibrationToJsonText(testing::ExportTestCalibration())); });
  const CalibrationInput in = ReadCalibrationInput(fifo);
  writer.join();
  EXPECT_EQ(Parameters(in.calibration), Parameters(testing::ExportTestCalibration()));
}

// The report's metadata: the session's identity, and the default procedure's limits only when
// the session ran it.
TEST_F(CalibrationInputTest, ReportOfASessionCarriesItsMetaAndItsProcedureLimits) {
  const Procedure seed = LoadProcedure(FullProcedurePath());
  MakeSession(true, seed.title);
  ReportRequest request;
  request.input = path_;
  request.default_procedure_path = FullProcedurePath();
  const ReportInputs in = ReportInputsFor(request);
  EXPECT_EQ(in.meta.device, "SN-0042");
  EXPECT_EQ(in.meta.session_path, path_);
  EXPECT_EQ(in.meta.procedure, seed.title);
  EXPECT_TRUE(in.limits.has_value());
  ASSERT_TRUE(in.nominal_bias_counts.has_value());
  EXPECT_TRUE(*in.nominal_bias_counts == seed.nominal.bias_counts);
}

// A session recorded before the procedure was renamed names it by its former title ("Seed
// calibration: ..."): it ran this procedure, so its report takes this procedure's limits.
TEST_F(CalibrationInputTest, ReportOfASessionUnderTheProceduresFormerTitleCarriesItsLimits) {
  const Procedure full = LoadProcedure(FullProcedurePath());
  ASSERT_FALSE(full.former_titles.empty());
  MakeSession(true, "Seed calibration: level, 9 prism poses, 9 turntable runs, fit, diagnosis");
  ReportRequest request;
  request.input = path_;
  request.default_procedure_path = FullProcedurePath();
  const ReportInputs in = ReportInputsFor(request);
  EXPECT_EQ(in.meta.procedure, full.former_titles.front());
  EXPECT_TRUE(in.limits.has_value());
  ASSERT_TRUE(in.nominal_bias_counts.has_value());
  EXPECT_TRUE(*in.nominal_bias_counts == full.nominal.bias_counts);
}

TEST_F(CalibrationInputTest, ReportOfAnotherProcedureStatesNoLimits) {
  MakeSession(true, "a procedure of another lab");
  ReportRequest request;
  request.input = path_;
  request.default_procedure_path = FullProcedurePath();
  EXPECT_FALSE(ReportInputsFor(request).limits.has_value());
  const fs::path file = dir_ / "cal.json";
  WriteText(file, CalibrationToJsonText(testing::ExportTestCalibration()));
  request.input = file.string();
  const ReportInputs from_file = ReportInputsFor(request);
  EXPECT_FALSE(from_file.limits.has_value());  // a calibration file names no procedure
  EXPECT_TRUE(from_file.meta.device.empty());
}

}  // namespace
}  // namespace accelcal::calibration_input_test
