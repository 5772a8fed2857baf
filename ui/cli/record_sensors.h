// `accelcal record --sensors N` (issue 31): several sensors at once (the virtual bench's plate of
// N boards, a scenario's [fixture], a fixture file or the 3N columns of one line), one
// continuous recording per sensor beside -o's name: `plate.txt` gives `plate.SIM01.txt`, ...
// (the sensor's serial before the extension), each as `record` writes one sensor's.
#pragma once

#include <csignal>
#include <memory>
#include <string>

#include "accelcal/acquire/source/sensor_set_source.h"

namespace accelcal::cli {

// `output`'s name with the serial before its extension ("a/plate.txt", "B01" -> "a/plate.B01.txt";
// no extension: "a/plate.B01"); a serial's characters other than letters, digits, '-', '_',
// '.' become '_'.
std::string SensorRecordingPath(const std::string& output, const std::string& serial);

// Records every sensor of `set` until `duration_s` of samples (0: until the source ends or
// Ctrl-C, which the caller's guard turns into *interrupted), status on stderr once a second
// unless quiet. A sensor that sent nothing gets no file (said, with its link's state).
void RecordSensorSet(SensorSetSource& set, const std::string& output, double duration_s, bool quiet,
                     volatile const std::sig_atomic_t* interrupted);

}  // namespace accelcal::cli
