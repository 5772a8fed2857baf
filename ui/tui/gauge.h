// Bar gauges drawn with characters, so that they read the same in monochrome.
#pragma once

#include <string>

namespace accelcal::ui {

// "[#####.....]" for `fraction` in 0..1 with `inner` cells between the brackets. At or beyond 1
// every cell is filled and the last one is '!' (over the limit); NaN draws "[----------]".
std::string Bar(double fraction, int inner);

}  // namespace accelcal::ui
