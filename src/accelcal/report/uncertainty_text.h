// A measured value and its expanded uncertainty as a certificate prints them (GUM 7.2.6): U
// rounded to two significant digits, the value to the same decimal place, so the digits shown
// are the digits the uncertainty supports ("2051.334 +- 0.044", not "2051.333812 +- 0.0441").
#pragma once

#include <string>

namespace accelcal {

struct RoundedResult {
  std::string value;        // "2051.334", "-0.0012"; "-" when not finite
  std::string uncertainty;  // "0.044"; "-" when not finite or not positive
};

// `value` and `expanded` rounded together (U up to two significant digits; a U of 0 or not
// finite leaves the value at 6 significant digits).
RoundedResult RoundToUncertainty(double value, double expanded);

}  // namespace accelcal
