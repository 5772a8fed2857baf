// A calibration written into a flight controller's own parameters over MAVLink (issue 30, "write
// back"): the ArduPilot or PX4 per-axis offset and scale as the exports compute them
// (io/export/ardupilot_params.h, px4_params.h: what the stack's model cannot carry is said by
// the same words), named for the IMU being calibrated.
//
// Applying: the current values are read first (the "before" a technician can go back to); then
// each PARAM_SET is sent and its PARAM_VALUE echo awaited; every parameter is read back at the
// end and compared. The first parameter that is not echoed, or echoed with another value, stops
// it: the outcome says which were written (echoed as sent), which was not (and what the vehicle
// answered), and which were never sent. Nothing silent, nothing half-done without a word.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "accelcal/app/device/vehicle_calibration.h"
#include "accelcal/calibration/calibration.h"
#include "accelcal/io/export/diagonal_correction.h"

namespace accelcal {

struct WritebackPlan {
  FlightStack stack = FlightStack::kUnknown;
  int imu = 0;
  std::vector<ParamWrite> writes;
  std::vector<std::string> cannot_hold;  // as the file exports say it
  std::vector<std::string> notes;
};

// The driver's scaling of readings taken in a unit (a MAVLink stream's m/s^2 counts of 0.001
// m/s^2: 1000 counts per m/s^2, no zero-g level); nullopt for counts, whose scaling only the
// sensor's datasheet knows (then the caller gives it, as for `export-cal --to ardupilot`).
std::optional<DriverScaleOptions> DriverScaleOfUnit(const ReadingUnit& unit);

// Throws accelcal::Error for an unknown stack or IMU, or an invalid driver scaling.
WritebackPlan PlanWriteback(const Calibration& cal, FlightStack stack, int imu,
                            const DriverScaleOptions& driver);

// "PARAM_SET INS_ACCOFFS_X = 0.0123457 (REAL32)", one per write.
std::vector<std::string> DescribeWrites(const std::vector<ParamWrite>& writes);

struct WritebackOutcome {
  std::map<std::string, double> before;  // as read first
  std::vector<std::string> written;      // echoed with the value sent
  std::vector<std::string> not_sent;     // after a stop
  std::string failed;                    // the parameter that stopped it, and what was seen
  std::vector<std::string> reread_mismatches;  // read back other than sent (or not at all)
  bool ok() const { return failed.empty() && reread_mismatches.empty(); }
  // For the technician: what was there before, what was written, what was not.
  std::vector<std::string> Lines() const;
};

// Sends the writes to the vehicle on `link` (never throws for what the vehicle does: the outcome
// says it; throws accelcal::Error when no vehicle answers the link at all).
WritebackOutcome ApplyWrites(mavlink::Connection& link, FlightStack stack, const std::vector<ParamWrite>& writes,
                             const mavlink::ParamExchange& exchange = {});

}  // namespace accelcal
