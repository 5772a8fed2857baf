// Source specs: parsing, and the messages for bad ones.
#include "accelcal/acquire/source/source_spec.h"

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/acquire/source/serial_link.h"
#include "test_support.h"

namespace accelcal {
namespace {

using testing::Contains;

std::string ErrorOf(const std::string& spec, const SourceOptions& options = {}) {
  try {
    OpenSource(spec, options);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SourceSpecTest, ParsesEveryKind) {
  EXPECT_EQ(ParseSourceSpec("sim").kind, SourceKind::kSim);
  EXPECT_EQ(ParseSourceSpec("-").kind, SourceKind::kStdin);
  const SourceSpec file = ParseSourceSpec("file:dir/rec:1.txt");
  EXPECT_EQ(file.kind, SourceKind::kFile);
  EXPECT_EQ(file.path, "dir/rec:1.txt");
  const SourceSpec serial = ParseSourceSpec("serial:/dev/ttyUSB0@115200");
  EXPECT_EQ(serial.kind, SourceKind::kSerial);
  EXPECT_EQ(serial.path, "/dev/ttyUSB0");
  EXPECT_EQ(serial.baud, 115200);
  const SourceSpec tcp = ParseSourceSpec("tcp:beagle.local:5000");
  EXPECT_EQ(tcp.host, "beagle.local");
  EXPECT_EQ(tcp.port, 5000);
  const SourceSpec v6 = ParseSourceSpec("tcp:[::1]:6000");
  EXPECT_EQ(v6.host, "::1");
  EXPECT_EQ(v6.port, 6000);
}

TEST(SourceSpecTest, BadSpecsSayWhatWasExpected) {
  EXPECT_EQ(ErrorOf("foo"),
            "unknown source 'foo': expected sim, file:PATH, serial:DEVICE@BAUD, tcp:HOST:PORT, mavlink:LINK, iio:NAME or -");
  EXPECT_TRUE(Contains(ErrorOf("serial:/dev/ttyUSB0"), "expected serial:DEVICE@BAUD"));
  EXPECT_TRUE(Contains(ErrorOf("serial:/dev/ttyUSB0@fast"), "'fast' is not a positive"));
  EXPECT_TRUE(Contains(ErrorOf("tcp:host"), "expected tcp:HOST:PORT"));
  EXPECT_TRUE(Contains(ErrorOf("tcp:host:70000"), "port '70000' is not a number in 1..65535"));
  EXPECT_TRUE(Contains(ErrorOf("file:"), "expected file:PATH"));
  EXPECT_TRUE(Contains(ErrorOf("file:/no/such/file"), "cannot open '/no/such/file'"));
}

TEST(SourceSpecTest, UnsupportedBaudRateListsTheSupportedOnes) {
  const std::string e = ErrorOf("serial:/dev/ttyUSB0@12345");
  EXPECT_TRUE(Contains(e, "unsupported baud rate 12345")) << e;
  EXPECT_TRUE(Contains(e, "9600, 19200, 38400, 57600, 115200")) << e;
  EXPECT_TRUE(IsSupportedBaudRate(115200));
  EXPECT_FALSE(IsSupportedBaudRate(115201));
}

TEST(SourceSpecTest, OptionsAreValidatedFirst) {
  SourceOptions o;
  o.dead_after_s = 0.0;
  EXPECT_TRUE(Contains(ErrorOf("sim", o), "dead_after_s")) << ErrorOf("sim", o);
  o = {};
  o.sim.speed = 0.5;
  EXPECT_TRUE(Contains(ErrorOf("sim", o), "speed = 0.5")) << ErrorOf("sim", o);
  o = {};
  o.gap_factor = 1.0;
  EXPECT_TRUE(Contains(ErrorOf("-", o), "gap_factor")) << ErrorOf("-", o);
}

TEST(SourceSpecTest, DescribeGivesTheSpecBack) {
  EXPECT_EQ(OpenSource("sim", {})->Describe(), "sim");
  EXPECT_EQ(OpenSource("-", {})->Describe(), "-");
  EXPECT_EQ(OpenSource("serial:/dev/ttyUSB0@115200", {})->Describe(), "serial:/dev/ttyUSB0@115200");
  EXPECT_EQ(OpenSource("tcp:localhost:5000", {})->Describe(), "tcp:localhost:5000");
  EXPECT_EQ(OpenSource("sim", {})->bench() != nullptr, true);
  EXPECT_EQ(OpenSource("-", {})->bench(), nullptr);
}

}  // namespace
}  // namespace accelcal
