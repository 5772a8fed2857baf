// The program's version ("0.1.0"), from CMakeLists.txt's project() (generated into one file,
// version.cpp, so a version bump recompiles that file alone).
#pragma once

namespace accelcal {

extern const char* const kAccelcalVersion;

}  // namespace accelcal
