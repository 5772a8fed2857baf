// A vehicle's own accelerometer calibration taken back out of its readings, and a calibration
// planned for its parameters: the names per stack and IMU, the undo of offsets, scales and the
// board rotation (checked by applying the vehicle's correction and undoing it), and what cannot
// be undone; the write-back commands at the end of a session of several IMUs.
#include <gtest/gtest.h>

#include "accelcal/acquire/mavlink/sensor_orientation.h"
#include "accelcal/app/device/vehicle_imus_writeback.h"
#include "accelcal/app/device/vehicle_writeback.h"
#include "test_support.h"

namespace accelcal {
namespace {

using testing::Contains;

mavlink::ParamValue Real(float v) {
  mavlink::ParamValue p;
  p.value = v;
  p.type = mavlink::kParamTypeReal32;
  return p;
}

VehicleAccelParams ArduPilotImu1(int orientation) {
  VehicleAccelParams p;
  p.stack = FlightStack::kArduPilot;
  p.imu = 1;
  p.names = AccelParamNamesFor(FlightStack::kArduPilot, 1);
  const float offsets[3] = {0.2f, -0.1f, 0.3f}, scales[3] = {1.01f, 0.98f, 1.02f};
  for (size_t j = 0; j < 3; ++j) {
    p.values[p.names.offset[j]] = Real(offsets[j]);
    p.values[p.names.scale[j]] = Real(scales[j]);
  }
  mavlink::ParamValue o;
  o.type = mavlink::kParamTypeInt8;
  o.value = static_cast<float>(orientation);  // ArduPilot casts integers to float
  p.values["AHRS_ORIENTATION"] = o;
  o.value = 0;
  p.values["INS_TCAL2_ENABLE"] = o;
  return p;
}

TEST(VehicleCalibrationTest, NamesPerStackAndImu) {
  const AccelParamNames a = AccelParamNamesFor(FlightStack::kArduPilot, 2);
  EXPECT_EQ(a.offset[0], "INS_ACC3OFFS_X");
  EXPECT_EQ(a.scale[2], "INS_ACC3SCAL_Z");
  EXPECT_EQ(a.device_id, "INS_ACC3_ID");
  EXPECT_EQ(a.thermal, "INS_TCAL3_ENABLE");
  EXPECT_EQ(AccelParamNamesFor(FlightStack::kArduPilot, 0).offset[1], "INS_ACCOFFS_Y");
  const AccelParamNames p = AccelParamNamesFor(FlightStack::kPx4, 1);
  EXPECT_EQ(p.offset[1], "CAL_ACC1_YOFF");
  EXPECT_EQ(p.scale[0], "CAL_ACC1_XSCALE");
  EXPECT_EQ(p.sensor_rotation, "CAL_ACC1_ROT");
  EXPECT_THROW(AccelParamNamesFor(FlightStack::kPx4, 3), Error);
  EXPECT_THROW(AccelParamNamesFor(FlightStack::kUnknown, 0), Error);
}

TEST(VehicleCalibrationTest, TheUndoInvertsTheVehiclesCorrection) {
  for (int orientation : {0, 2, 10, 28, 41}) {
    const VehicleAccelParams p = ArduPilotImu1(orientation);
    std::string why;
    const std::optional<mavlink::AccelUndo> undo = UndoOf(p, &why);
    ASSERT_TRUE(undo) << why;
    // The vehicle: R ((a - off) .* scale), R written out from the name's angles.
    const mavlink::SensorOrientation o = *mavlink::FindSensorOrientation(orientation);
    const Eigen::Vector3d sensor(0.3, -9.7, 1.2);
    const Eigen::Vector3d off(0.2f, -0.1f, 0.3f), scale(1.01f, 0.98f, 1.02f);
    const Eigen::Vector3d sent = o.BodyFromSensor() * (sensor - off).cwiseProduct(scale);
    EXPECT_LT((undo->SensorFromSent(sent) - sensor).norm(), 1e-12) << orientation;
    EXPECT_TRUE(Contains(undo->description, "INS_ACC2OFFS (0.2")) << undo->description;
  }
  // ROLL_180_YAW_90 maps (x, y, z) to (y, x, -z), as ArduPilot's rotate() writes it out.
  const Eigen::Vector3d v = mavlink::FindSensorOrientation(10)->BodyFromSensor() * Eigen::Vector3d(1, 2, 3);
  EXPECT_LT((v - Eigen::Vector3d(2, 1, -3)).norm(), 1e-12);
}

TEST(VehicleCalibrationTest, WhatCannotBeUndoneIsSaid) {
  std::string why;
  VehicleAccelParams p = ArduPilotImu1(38);
  EXPECT_FALSE(UndoOf(p, &why));
  EXPECT_TRUE(Contains(why, "AHRS_ORIENTATION = 38 is a rotation accelcal cannot undo")) << why;
  p = ArduPilotImu1(0);
  p.values["INS_TCAL2_ENABLE"].value = 1;
  EXPECT_FALSE(UndoOf(p, &why));
  EXPECT_TRUE(Contains(why, "INS_TCAL2_ENABLE is on")) << why;
  p = ArduPilotImu1(0);
  p.values.erase("INS_ACC2SCAL_Y");
  EXPECT_FALSE(UndoOf(p, &why));
  EXPECT_TRUE(Contains(why, "did not answer for INS_ACC2SCAL_Y")) << why;
  const std::vector<ParamWrite> reset = ResetWrites(ArduPilotImu1(0));
  ASSERT_EQ(reset.size(), 6u);
  EXPECT_EQ(reset[0].name, "INS_ACC2OFFS_X");
  EXPECT_EQ(reset[5].value, 1.0);
}

TEST(VehicleWritebackTest, PlanNamedForTheImuFromTheUnitsScaling) {
  Calibration cal;
  cal.model.bias_counts = Eigen::Vector3d(120.0, -50.0, 300.0);  // counts of 0.001 m/s^2
  cal.model.scale_counts_per_mps2 = Eigen::Vector3d(1002.0, 998.0, 1010.0);
  cal.uncertainty.bias_counts = Eigen::Vector3d::Constant(1.0);
  cal.uncertainty.scale_counts_per_mps2 = Eigen::Vector3d::Constant(0.5);
  const std::optional<DriverScaleOptions> driver =
      DriverScaleOfUnit(ReadingUnit{ReadingUnit::Kind::kMps2, 1000.0});
  ASSERT_TRUE(driver);
  EXPECT_FALSE(DriverScaleOfUnit(ReadingUnit{}));
  const WritebackPlan plan = PlanWriteback(cal, FlightStack::kArduPilot, 1, *driver);
  ASSERT_EQ(plan.writes.size(), 6u);
  EXPECT_EQ(plan.writes[0].name, "INS_ACC2OFFS_X");
  EXPECT_DOUBLE_EQ(plan.writes[0].value, 0.12);          // m/s^2
  EXPECT_DOUBLE_EQ(plan.writes[4].value, 1000.0 / 998.0);  // INS_ACC2SCAL_Y
  EXPECT_TRUE(Contains(plan.cannot_hold.front(), "misalignment")) << plan.cannot_hold.front();
  for (const std::string& note : plan.notes) EXPECT_FALSE(Contains(note, "INS_ACCOFFS_")) << note;
  const WritebackPlan px4 = PlanWriteback(cal, FlightStack::kPx4, 0, *driver);
  EXPECT_EQ(px4.writes[3].name, "CAL_ACC0_XSCALE");
  EXPECT_EQ(DescribeWrites(px4.writes)[0], "PARAM_SET CAL_ACC0_XOFF = 0.12 (REAL32)");
}

// The end of a session of a vehicle's IMUs: each IMU's exact command (its sensor, its imu=, the
// procedure's scaling only for counts, a path quoted for the shell), or why nothing is written.
TEST(VehicleWritebackTest, EachImuOfASessionItsOwnCommandOrWhyNot) {
  Calibration mps2;
  mps2.reading_unit = ReadingUnit{ReadingUnit::Kind::kMps2, 1000.0};
  Calibration counts;  // RAW_IMU
  const MavlinkSourceSpec link = ParseMavlinkSpec("mavlink:tcp:127.0.0.1:5760");
  const std::vector<std::string> lines = ImuWritebackLines(
      "/lab/fc 1.db", link, "/p/autopilot.toml",
      {{0, 1, "ACC0", "PASS", counts, "", true},
       {1, 2, "ACC1", "FAIL", mps2, "", true},
       {2, 3, "ACC2", "NO CALIBRATION", std::nullopt, "no capture of this sensor was accepted", true}});
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[1], "  IMU 0 (ACC0, PASS): accelcal export-cal '/lab/fc 1.db' --sensor 1 --to "
                      "mavlink:tcp:127.0.0.1:5760,imu=0 --procedure /p/autopilot.toml --apply");
  EXPECT_EQ(lines[2], "  IMU 1 (ACC1, FAIL: read its report before writing it): accelcal export-cal "
                      "'/lab/fc 1.db' --sensor 2 --to mavlink:tcp:127.0.0.1:5760,imu=1 --apply");
  EXPECT_EQ(lines[3], "  IMU 2 (ACC2): nothing to write: no capture of this sensor was accepted");
  const std::vector<std::string> as_is =
      ImuWritebackLines("fc.db", link, "p.toml", {{1, 2, "ACC1", "PASS", mps2, "", false}});
  EXPECT_TRUE(Contains(as_is[1], "IMU 1 (ACC1): nothing to write: the vehicle's own calibration was left in "
                                 "its readings"))
      << as_is[1];
  EXPECT_TRUE(Contains(as_is[1], "device-info --source mavlink:tcp:127.0.0.1:5760,imu=1 --reset --apply"))
      << as_is[1];
}

}  // namespace
}  // namespace accelcal
