// The `--columns` list of a line that carries several sensors (issue 31): a logger printing
// `t ax ay az ax ay az ...`, one group per sensor. The k-th ax, ay and az are sensor k's; t is
// shared; temp_c is shared when named once, or sensor k's when named once per sensor.
// Each sensor gets the list one sensor's reader takes (sample_reader.h): the line's columns with
// every other sensor's marked "-", so the rules of a line (fields, separators, time) stay the
// one reader's.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "accelcal/base/sample_columns.h"

namespace accelcal {

// One layout per sensor, in order (at least one); empty with *error set when the list names an
// unknown column, or ax, ay, az a different number of times, or t twice, or temp_c neither once
// nor once per sensor.
std::vector<std::vector<NamedColumn>> SplitSensorColumns(std::string_view text,
                                                         std::string* error);

}  // namespace accelcal
