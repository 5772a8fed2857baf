// The answer to the wizard's "Refit with new inputs?" on a finished session (issue 27, item 5):
// the corrections `accelcal refit` takes, typed on one line, each starting with what it corrects
// and separated by ';':
//     gravity 9.78030 +- 0.00002; equipment ruler id RUL-07 cal C-2291; turntable cal T-118
//     gravity lat -34.9 alt 43; device SN-42; operator Ana Paz; place Lab 2, bench 3
// "gravity" takes what the welcome takes (gravity_input.h), "equipment" the welcome's equipment
// answer (equipment_input.h: the segments after it that start with an item's role are its too),
// "device", "operator" and "place" the text after the word.
#pragma once

#include <string>

#include "accelcal/app/refit_session.h"

namespace accelcal {

struct RefitAnswer {
  RefitRequest request;  // the corrections (the session's name, paths and time not set)
  std::string error;     // why the answer was refused; empty when understood
  bool ok() const { return error.empty(); }
};

RefitAnswer ParseRefitAnswer(const std::string& text);

}  // namespace accelcal
