// Issue 17, item 4: what a user types (the device, the date, a file's name) goes into every
// exported file's comment; none of it may become code, a parameter or a YAML key. Each export is
// made with hostile text and read back the way its consumer reads it: the C header compiled
// (cc -std=c99 -Wall -Wextra -Werror -pedantic) with a program that uses the injected symbol
// (it must not compile) and one that only includes it (it must); the parameter files parsed
// line by line (every line that is not a comment must be one of the six parameters); Kalibr's
// YAML split at every line break YAML 1.1 knows (LF, CR, NEL, U+2028, U+2029).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "accelcal/base/safe_text.h"
#include "accelcal/io/export/ardupilot_params.h"
#include "accelcal/io/export/c_header.h"
#include "accelcal/io/export/kalibr_imu_yaml.h"
#include "accelcal/io/export/px4_params.h"
#include "export_test_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

namespace fs = std::filesystem;
using testing::ExportTestCalibration;

// Each of these tries to end the comment it is written into.
const std::vector<std::string> kHostileDevices = {
    "SN1 */ int injected = 1; /*",
    "SN1 *\\/ */\nint injected = 1;\n/* ",
    "SN1\nINS_ACCOFFS_X,9\nCAL_ACC0_XOFF,9",
    "SN1\r\n1\t1\tCAL_ACC0_XOFF\t9\t9\r\nINS_ACCSCAL_Y,2",
    "SN1\xC2\x85rostopic: /injected\xE2\x80\xA8update_rate: 1.0\xE2\x80\xA9x: 1",
    "SN1 ?" "?/\n?" "?= /* nested",  // trigraphs ??/ and ??= (split: C++ warns on them)
    "SN1 \x1B[2J\x07\xFF\xFE",
};

ExportContext Hostile(const std::string& device) {
  return {device, "2025-03-01\n#define injected 1", "cal.json */ int injected2 = 2; /*"};
}

class HostileCHeader : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("accelcal_hostile_{}", ::getpid());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  bool Compiles(const std::string& header, const std::string& main_body) {
    std::ofstream(dir_ / "accel_cal.h") << header;
    std::ofstream(dir_ / "main.c") << "#include \"accel_cal.h\"\nint main(void) {" << main_body << "}\n";
    return std::system(fmt::format("cc -std=c99 -Wall -Wextra -Werror -pedantic -o {0}/prog {0}/main.c -lm "
                                   "> {0}/cc.log 2>&1",
                                   dir_.string())
                           .c_str()) == 0;
  }

  fs::path dir_;
};

TEST_F(HostileCHeader, DeviceTextNeverBecomesCode) {
  for (const std::string& device : kHostileDevices) {
    const std::string header = ExportCHeader(ExportTestCalibration(), Hostile(device)).text;
    EXPECT_TRUE(Compiles(header, " return 0; ")) << "the header does not compile with device:\n" << device
                                                 << "\n" << header;
    EXPECT_FALSE(Compiles(header, " return injected; ")) << "the device defined a symbol:\n" << header;
    EXPECT_FALSE(Compiles(header, " return injected2; ")) << "the source defined a symbol:\n" << header;
    // The whole comment is one block that ends once, right before the include guard.
    EXPECT_EQ(header.find("*/"), header.find(" */\n#ifndef ACCELCAL_CALIBRATION_H") + 1) << header;
  }
}

// Every line that is not a comment, split at LF only (what both stacks' loaders do; a CR is
// part of the line and would make a bad parameter name).
std::vector<std::string> ParameterLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  return lines;
}

TEST(HostileParameterFiles, DeviceTextAddsNoParameter) {
  DriverScaleOptions driver;
  driver.nominal_scale_counts_per_mps2 = Eigen::Vector3d::Constant(34.8);
  driver.nominal_bias_counts = Eigen::Vector3d::Constant(2048.0);
  for (const std::string& device : kHostileDevices) {
    const std::string ardupilot = ExportArduPilotParams(ExportTestCalibration(), driver, Hostile(device)).text;
    std::set<std::string> names;
    for (const std::string& line : ParameterLines(ardupilot)) names.insert(line.substr(0, line.find(',')));
    EXPECT_EQ(names, (std::set<std::string>{"INS_ACCOFFS_X", "INS_ACCOFFS_Y", "INS_ACCOFFS_Z", "INS_ACCSCAL_X",
                                            "INS_ACCSCAL_Y", "INS_ACCSCAL_Z"}))
        << ardupilot;
    EXPECT_EQ(ParameterLines(ardupilot).size(), 6u) << ardupilot;
    EXPECT_EQ(ardupilot.find('\r'), std::string::npos);

    const std::string px4 = ExportPx4Params(ExportTestCalibration(), {driver, std::nullopt}, Hostile(device)).text;
    names.clear();
    for (const std::string& line : ParameterLines(px4)) {
      EXPECT_EQ(line.rfind("1\t1\tCAL_ACC0_", 0), 0u) << line;
      names.insert(line.substr(4, line.find('\t', 4) - 4));
    }
    EXPECT_EQ(names, (std::set<std::string>{"CAL_ACC0_XOFF", "CAL_ACC0_YOFF", "CAL_ACC0_ZOFF", "CAL_ACC0_XSCALE",
                                            "CAL_ACC0_YSCALE", "CAL_ACC0_ZSCALE"}))
        << px4;
    EXPECT_EQ(ParameterLines(px4).size(), 6u) << px4;
  }
}

// Lines as YAML 1.1 (PyYAML, which Kalibr uses) breaks them.
std::vector<std::string> YamlLines(const std::string& text) {
  std::vector<std::string> lines(1);
  for (size_t i = 0; i < text.size(); ++i) {
    const std::string_view rest(text.data() + i, text.size() - i);
    size_t skip = 0;
    if (text[i] == '\n' || text[i] == '\r') skip = 1;
    if (rest.rfind("\xC2\x85", 0) == 0) skip = 2;
    if (rest.rfind("\xE2\x80\xA8", 0) == 0 || rest.rfind("\xE2\x80\xA9", 0) == 0) skip = 3;
    if (skip == 0) {
      lines.back() += text[i];
    } else {
      lines.emplace_back();
      i += skip - 1;
    }
  }
  return lines;
}

TEST(HostileKalibr, CommentTextAddsNoKey) {
  for (const std::string& device : kHostileDevices) {
    KalibrImuYamlOptions o;
    o.accelerometer_noise_density = 0.0018;
    o.accelerometer_random_walk = 4.5e-05;
    o.update_rate_hz = 100.0;
    o.comment = fmt::format("by accelcal export-cal: {}.\nsecond line {}", DescribeOrigin(ExportTestCalibration(),
                                                                                          Hostile(device)), device);
    const std::string yaml = WriteKalibrImuYaml(o).text;
    std::set<std::string> keys;
    for (const std::string& line : YamlLines(yaml)) {
      if (line.empty() || line[0] == '#') continue;
      keys.insert(line.substr(0, line.find(':')));
      // PyYAML refuses a stream with a control character anywhere, comments included.
      for (char c : line) EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 && c != '\t') << line;
    }
    EXPECT_EQ(keys, (std::set<std::string>{"accelerometer_noise_density", "accelerometer_random_walk", "rostopic",
                                           "update_rate"}))
        << yaml;
    EXPECT_TRUE(IsValidUtf8(yaml)) << yaml;  // PyYAML decodes the whole stream first
  }
}

TEST(HostileExports, NonFiniteNumbersAreNeverWritten) {
  Calibration cal = ExportTestCalibration();
  DriverScaleOptions driver;
  driver.nominal_scale_counts_per_mps2 = Eigen::Vector3d::Constant(1e-310);  // the offset (b - B) / S overflows
  driver.nominal_bias_counts = Eigen::Vector3d::Zero();
  EXPECT_THROW(ExportArduPilotParams(cal, driver, {}), Error);
  EXPECT_THROW(ExportPx4Params(cal, {driver, std::nullopt}, {}), Error);
  cal.model.scale_counts_per_mps2.x() = 1e-320;  // M = T K^-1 overflows
  EXPECT_THROW(ExportCHeader(cal, {}), Error);
}

}  // namespace
}  // namespace accelcal
