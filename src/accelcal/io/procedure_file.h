// Reading a procedure (session/procedure.h) from its TOML file (docs/guide.md, "Procedures").
#pragma once

#include <string>
#include <string_view>

#include "accelcal/session/procedure.h"

namespace accelcal {

// Throws accelcal::InputError "FILE:LINE:COLUMN: what" for malformed TOML, an unknown key, a
// wrong type or value, a duplicate step id.
Procedure ParseProcedure(std::string_view toml_text, const std::string& source_name);
// Reads and parses `path`; throws accelcal::Error when it cannot be read.
Procedure LoadProcedure(const std::string& path);

}  // namespace accelcal
