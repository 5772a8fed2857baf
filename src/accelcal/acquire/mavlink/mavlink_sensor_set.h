// The IMUs of one autopilot over one MAVLink connection (issue 31): a flight controller with two
// or three accelerometers calibrated in one session, each IMU instance one sensor of the set.
// Sensor i is IMU instance i (the id field of HIGHRES_IMU and RAW_IMU; SCALED_IMU, SCALED_IMU2,
// SCALED_IMU3 for 0, 1, 2), the fixture's sensor i its serial. Asked as
//   accelcal wizard --source mavlink:udp:0.0.0.0:14550 --fixture vehicle.toml   (3 sensors)
//   accelcal wizard --source mavlink:udp:0.0.0.0:14550 --sensors 3
//
// One connection, one rate request per message, one heartbeat watch: what mavlink_source.h says
// of a single IMU holds for each instance (the message chosen per instance, its clock, reboots,
// lost frames). Each instance has its own status: an instance whose messages stop goes dead
// ("heartbeats from ... arrive, but no ... of IMU 2") while the others stay up; the link's own
// events (lost, bad frames, the rate request's fallback) are every instance's.
//
// The vehicle's own calibration: each IMU instance's readings arrive corrected by that IMU's
// stored calibration (ArduPilot's INS_ACCOFFS, INS_ACC2OFFS, INS_ACC3OFFS ...; PX4's CAL_ACCn_*).
// The app reads each instance's parameters over the set's one link and undoes each on its own
// lane (instances(): app/device/vehicle_session.h, PrepareVehicleSource), as for one IMU. The
// write-back is one IMU at a time (mavlink:...,imu=N).
#pragma once

#include <memory>
#include <string>

#include "accelcal/acquire/mavlink/mavlink_source.h"
#include "accelcal/acquire/source/sensor_set_source.h"

namespace accelcal {

class MavlinkSensorSet final : public SensorSetSource {
 public:
  // Reads IMU instances 0 .. fixture's sensors - 1 (at most 3); throws accelcal::Error for a
  // spec that names its own imu= (one instance) or more than three sensors.
  MavlinkSensorSet(const std::string& spec, Fixture fixture, const SourceOptions& options);

  std::string Describe() const override;
  const Fixture& fixture() const override { return fixture_; }
  ReadResult Read(double timeout_s, SensorSetSamples* out) override;
  const SourceStatus& status(std::size_t sensor) const override { return source_->status(sensor); }
  // What the IMU instance of `sensor` reads ("HIGHRES_IMU of IMU 1 from ...").
  std::string DescribeReading(std::size_t sensor) const { return source_->DescribeReading(sensor); }
  // The one link and its IMU lanes (lane i: sensor i), for the vehicle's parameters and each
  // instance's undo (MavlinkSource::SetUndo).
  MavlinkSource& instances() { return *source_; }

 private:
  Fixture fixture_;
  std::unique_ptr<MavlinkSource> source_;
};

}  // namespace accelcal
