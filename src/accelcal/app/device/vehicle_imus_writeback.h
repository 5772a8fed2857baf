// The write-back at the end of a session of a vehicle's several IMUs (issue 31,
// acquire/mavlink/mavlink_sensor_set.h): each IMU is written on its own, by the command a
// single IMU's write-back is (`accelcal export-cal SESSION --sensor N --to mavlink:LINK,imu=N-1
// --apply`: vehicle_writeback.h's plan, each PARAM_SET echoed, every value read back), named
// per IMU in the session's closing lines, or why there is nothing to write for it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "accelcal/acquire/mavlink/mavlink_source.h"
#include "accelcal/calibration/calibration.h"

namespace accelcal {

// One IMU of the session as its end found it.
struct ImuWriteback {
  int imu = 0;                 // the IMU instance (0, 1, 2)
  int sensor = 1;              // the session's sensor number, 1-based (export-cal --sensor)
  std::string serial;
  std::string verdict;         // the report's ("PASS", "FAIL", ...), or "NO CALIBRATION"
  std::optional<Calibration> calibration;
  std::string reason;          // why there is no calibration
  bool undone = false;         // the vehicle's own calibration taken out of its readings
};

// The closing lines: a heading, then a line per IMU ending with its exact command, or saying why
// nothing is to be written (no calibration; the vehicle's calibration left in its readings).
// `link`: the set's link (its imu= replaced per IMU). `procedure_path`: given to a calibration
// in counts (RAW_IMU), whose driver scaling is the procedure's, as the write-back step does.
std::vector<std::string> ImuWritebackLines(const std::string& session_path, const MavlinkSourceSpec& link,
                                           const std::string& procedure_path,
                                           const std::vector<ImuWriteback>& imus);

}  // namespace accelcal
