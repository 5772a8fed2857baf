// What is checked about a sample source before a command creates anything (a session file): a
// serial port must exist. While a session runs a port that goes away (a cable pulled) is waited
// for and retried (acquire/source/source_spec.h); at the start, a port that is not there is a
// mistyped name or an adapter not plugged in, and a session file made for it would only be
// litter for `accelcal sessions`.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "accelcal/acquire/source/sample_source.h"
#include "accelcal/acquire/source/sensor_set_source.h"

namespace accelcal::cli {

// Throws accelcal::Error naming the port and what to check when `spec` is serial:DEVICE@BAUD
// and DEVICE does not exist. Other specs are left to OpenSource.
void RefuseAbsentSerialPort(const std::string& spec);

// A MAVLink source: reads the vehicle's own accelerometer calibration, says it on `say`
// (nullable), and takes it back out of the samples (`choice` "undo") or leaves it in ("as-is");
// returns what it said (the wizard shows it at the welcome and records it). Throws
// accelcal::Error (before anything is created) when it cannot be undone or no vehicle answers,
// having said the calibration on `say_when_refused` (nullable). Other sources: nothing.
std::vector<std::string> PrepareVehicle(SampleSource& source, const std::string& choice, std::FILE* say,
                                        std::FILE* say_when_refused);

// The same for a set of sensors: a vehicle's IMU instances over one MAVLink link
// (mavlink_sensor_set.h), each IMU's calibration read, said (a block per IMU) and undone on its
// own; refused when one IMU's cannot be undone. Other sets: nothing.
std::vector<std::string> PrepareVehicle(SensorSetSource& set, const std::string& choice, std::FILE* say,
                                        std::FILE* say_when_refused);

}  // namespace accelcal::cli
