// What a wizard session is started with (the command line's choices): its name, the defaults
// the welcome offers, the quiet period of the noise floor, the clocks and where the report goes.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "accelcal/base/gravity.h"

namespace accelcal {

class MavlinkSource;

struct WizardOptions {
  std::string session_name = "session";  // shown in the view and in the calibration's source
  std::string default_operator;          // offered at the welcome (may be empty)
  std::string default_device;            // device serial offered at the welcome (may be empty)
  // The welcome's default gravity answer (the command line's --gravity / --latitude); the
  // standard value when none was given. What the operator answers is used for the fit and
  // the checks, and recorded in the session.
  GravitySpec gravity;
  // Before the first capture of a run the sensor rests this long to measure the noise floor,
  // s; > 0.
  double quiet_period_s = 2.0;
  // The computer's clock for record gaps, s since the Unix epoch; empty = the system clock
  // (tests give their own).
  std::function<double()> wall_now_s;
  // Non-empty: the report step also writes the calibration report beside this session file
  // (report_files.h: SESSION.report.html and SESSION.report.txt). Empty: nothing is written.
  std::string report_beside = {};
  // The lab or bench offered at the welcome (may be empty): the report's "place".
  std::string default_place = {};
  // What the source's device already holds and what was done with it (a MAVLink vehicle's own
  // accelerometer calibration: read, then taken out of the readings or left in; app/device/
  // vehicle_session.h), one fact per line: shown at the welcome and recorded with its answers.
  // Empty for a source without such a device.
  std::vector<std::string> device_lines = {};
  // The MAVLink vehicle behind the session's source (the source itself, or inside the remote
  // bench's wrapper), borrowed: the write-back step (steps/write_back_step.cpp) writes the
  // calibration into it through the source's own link. nullptr for any other source.
  MavlinkSource* vehicle = nullptr;

  // Empty when the options are usable; else why not.
  std::string Validate() const {
    if (!(quiet_period_s > 0.0)) return "quiet_period_s must be positive";
    if (std::string why = gravity.Validate(); !why.empty()) return "gravity: " + why;
    return "";
  }
};

}  // namespace accelcal
