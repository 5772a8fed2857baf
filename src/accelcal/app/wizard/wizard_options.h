// What a wizard session is started with (the command line's choices): its name, the defaults
// the welcome offers, the quiet period of the noise floor, the clocks and where the report goes.
#pragma once

#include <functional>
#include <string>

#include "accelcal/base/gravity.h"

namespace accelcal {

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

  // Empty when the options are usable; else why not.
  std::string Validate() const {
    if (!(quiet_period_s > 0.0)) return "quiet_period_s must be positive";
    if (!(fixed_duration_s >= 0.0)) return "fixed_duration_s must not be negative";
    if (std::string why = gravity.Validate(); !why.empty()) return "gravity: " + why;
    return "";
  }
};

}  // namespace accelcal
