// IIO scan types as the kernel writes them, and records laid out as the kernel lays them out
// (iio_compute_scan_bytes): every element aligned to its own size, the record to its largest.
#include <gtest/gtest.h>

#include "accelcal/acquire/iio/iio_device.h"
#include "accelcal/acquire/iio/iio_scan_type.h"
#include "test_support.h"

namespace accelcal {
namespace {

using testing::Contains;

IioScanType Parsed(const char* text) {
  std::string why;
  const std::optional<IioScanType> t = ParseIioScanType(text, &why);
  EXPECT_TRUE(t) << why;
  return t.value_or(IioScanType{});
}

TEST(IioScanTypeTest, SignedLittleEndianShifted) {
  const IioScanType t = Parsed("le:s12/16>>4\n");
  EXPECT_TRUE(t.is_signed);
  EXPECT_FALSE(t.big_endian);
  EXPECT_EQ(t.bits, 12);
  EXPECT_EQ(t.storage_bits, 16);
  EXPECT_EQ(t.shift, 4);
  // -5 in 12 bits shifted left by 4, little-endian: 0xFFB0.
  const std::uint8_t bytes[2] = {0xB0, 0xFF};
  EXPECT_EQ(t.Decode(bytes), -5);
  EXPECT_EQ(t.Describe(), "le:s12/16>>4");
}

TEST(IioScanTypeTest, UnsignedBigEndian) {
  const IioScanType t = Parsed("be:u10/16>>0");
  const std::uint8_t bytes[2] = {0xFF, 0xFF};  // the high bits beyond 10 are not the reading
  EXPECT_EQ(t.Decode(bytes), 1023);
  const std::uint8_t mid[2] = {0x02, 0x00};
  EXPECT_EQ(t.Decode(mid), 512);
}

TEST(IioScanTypeTest, RepeatAndLibiioCapitals) {
  const IioScanType t = Parsed("le:S16/16X3>>0");
  EXPECT_EQ(t.repeat, 3);
  EXPECT_EQ(t.ElementBytes(), 6);
  const IioScanType ts = Parsed("le:s64/64>>0");
  std::uint8_t bytes[8] = {0x00, 0xCA, 0x9A, 0x3B, 0, 0, 0, 0};  // 1e9
  EXPECT_EQ(ts.Decode(bytes), 1000000000);
}

TEST(IioScanTypeTest, WhatIsNotUnderstoodIsSaid) {
  std::string why;
  EXPECT_FALSE(ParseIioScanType("xx:s12/16>>4", &why));
  EXPECT_TRUE(Contains(why, "does not start with le: or be:")) << why;
  EXPECT_FALSE(ParseIioScanType("le:s12/16>>8", &why));
  EXPECT_TRUE(Contains(why, "12 bits shifted by 8 do not fit 16 bits of storage")) << why;
  EXPECT_FALSE(ParseIioScanType("le:s12/24>>0", &why));
  EXPECT_TRUE(Contains(why, "storage of 24 bits")) << why;
  EXPECT_FALSE(ParseIioScanType("le:f32/32>>0", &why));
  EXPECT_TRUE(Contains(why, "sign 'f'")) << why;
}

TEST(IioLayoutTest, ElementsAlignedTheRecordPadded) {
  IioDevice d;
  std::string why;
  d.axes[0].scan = IioScanElement{"accel_x", 0, *ParseIioScanType("le:s16/16>>0", &why), 0};
  d.axes[1].scan = IioScanElement{"accel_y", 1, *ParseIioScanType("le:s16/16>>0", &why), 0};
  d.axes[2].scan = IioScanElement{"accel_z", 2, *ParseIioScanType("le:s16/16>>0", &why), 0};
  d.timestamp = IioScanElement{"timestamp", 3, *ParseIioScanType("le:s64/64>>0", &why), 0};
  EXPECT_EQ(LayOutRecord(&d), 16);  // 3 x 2 bytes, the timestamp aligned to 8
  EXPECT_EQ(d.timestamp->offset, 8);
  EXPECT_EQ(d.axes[2].scan->offset, 4);
  d.timestamp.reset();
  d.axes[1].scan->type = *ParseIioScanType("le:s32/32>>0", &why);
  EXPECT_EQ(LayOutRecord(&d), 12);  // x at 0, y aligned to 4, z at 8, padded to 4
  EXPECT_EQ(d.axes[1].scan->offset, 4);
}

TEST(IioSpecTest, OptionsAndMistakes) {
  const IioSourceSpec s = ParseIioSpec("iio:iio:device1,root=/tmp/t,dev=/tmp/f,x=voltage0,y=voltage1,z=voltage2,rate=50,poll");
  EXPECT_EQ(s.device, "iio:device1");
  EXPECT_EQ(s.root, "/tmp/t");
  EXPECT_EQ(s.channels[2], "voltage2");
  EXPECT_DOUBLE_EQ(s.rate_hz, 50.0);
  EXPECT_TRUE(s.poll);
  EXPECT_THROW(ParseIioSpec("iio:adxl345,speed=3"), Error);
  EXPECT_THROW(ParseIioSpec("iio:,root=/x"), Error);
  EXPECT_THROW(ParseIioSpec("iio:adxl345,rate=-1"), Error);
}

}  // namespace
}  // namespace accelcal
