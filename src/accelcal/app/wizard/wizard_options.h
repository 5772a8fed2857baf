// What a wizard session is started with (the command line's choices): its name, the defaults
// the welcome offers, the quiet period of the noise floor, the clocks, where the report goes and
// what to say about the flags a resumed session does not use.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "accelcal/base/gravity.h"
#include "accelcal/session/equipment.h"

namespace accelcal {

// What the lab's register said of the bench's equipment (WizardOptions::check_equipment).
struct WelcomeLabCheck {
  std::vector<std::string> warnings;  // one line each: expired, running out, unknown to the lab
  std::string unreachable;            // non-empty: the lab could not be reached, and why (one line)
};
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
  // > 0: every capture this long, s (--fixed-duration: the fixed plan, for comparison); 0: the
  // procedure's [target] plans each capture's length (bench_plan.h), or, without a target, each
  // step's own duration.
  double fixed_duration_s = 0.0;
  // The lab's check of the bench's equipment (app/lab_equipment_check.h: WelcomeEquipmentCheck):
  // its warnings (expired, running out, unknown to the lab) are shown at the welcome, for the
  // procedure's items and again for the items the equipment answer names; a lab out of reach
  // is said there too (the session goes on, kept on the bench). Empty: no check.
  std::function<WelcomeLabCheck(const std::vector<EquipmentItem>&)> check_equipment = {};
  // The equipment answer offered at the welcome (equipment_input.h); empty: "keep" (the
  // procedure's). The virtual bench offers its lab's (virtual_lab.h).
  std::string default_equipment = {};
  // Said on the first screen of a session resumed (or already finished): the command line's
  // flags this run does not use, with what to do instead (app/refit_session.h).
  std::vector<std::string> notes = {};
  // What the source's device already holds and what was done with it (a MAVLink vehicle's own
  // accelerometer calibration: read, then taken out of the readings or left in; app/device/
  // vehicle_session.h), one fact per line: shown at the welcome and recorded with its answers.
  // Empty for a source without such a device.
  std::vector<std::string> device_lines = {};
  // The MAVLink vehicle behind the session's source (the source itself, or inside the remote
  // bench's wrapper), borrowed: the write-back step (steps/write_back_step.cpp) writes the
  // calibration into it through the source's own link. nullptr for any other source.
  MavlinkSource* vehicle = nullptr;
  // Said by the write-back step in place of a write when the session's vehicle is written back
  // elsewhere (a vehicle's several IMUs: each on its own at the session's end); empty: none.
  std::string write_back_elsewhere = {};

  // Empty when the options are usable; else why not.
  std::string Validate() const {
    if (!(quiet_period_s > 0.0)) return "quiet_period_s must be positive";
    if (!(fixed_duration_s >= 0.0)) return "fixed_duration_s must not be negative";
    if (std::string why = gravity.Validate(); !why.empty()) return "gravity: " + why;
    return "";
  }
};

}  // namespace accelcal
