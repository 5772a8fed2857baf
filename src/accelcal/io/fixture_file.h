// Reading a fixture (base/fixture.h) from its TOML file: the plate's name and one [[sensor]] per
// device under test, in the order of the shared source's sensors (a text line's column triples,
// a vehicle's IMU instances). tests/data/fixture/plate_8.toml is an example:
//
//   name = "plate 8"            # optional
//   placement_u_deg = 0.1       # optional: how square the plate is set on the turntable, 1-sigma
//                               # per rotation component (a jig ~0.1; absent: by hand, 0.5)
//   [[sensor]]
//   serial = "A0001"            # required, unique
//   x = "+y"                    # where the sensor's +x points on the plate (default "+x")
//   y = "-x"                    # where its +y points (default "+y"); +z follows, right-handed
//   offset_m = [0.05, 0, 0]     # its sensing point from the plate's reference point, m
//   source = "tcp:host:5000"    # optional: its own link (source_spec.h)
#pragma once

#include <string>
#include <string_view>

#include "accelcal/base/fixture.h"

namespace accelcal {

// Parses a fixture from TOML text; `source_name` names it in errors. Throws InputError
// (FILE:LINE:COLUMN) on a syntax error, an unknown key, a missing or repeated serial, an axis
// that is not one of +x -x +y -y +z -z, axes that are not perpendicular.
Fixture ParseFixture(std::string_view toml_text, const std::string& source_name);

// Reads and parses a fixture file. Throws Error "cannot open 'PATH': ..." when it cannot be
// read, InputError as above.
Fixture LoadFixture(const std::string& path);

}  // namespace accelcal
