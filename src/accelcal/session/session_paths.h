// Where sessions live: `--session FILE` puts one anywhere; by default they go to
// $XDG_DATA_HOME/accelcal/sessions/ (else ~/.local/share/accelcal/sessions/), one FILE.db per
// session named by its creation time (UTC), e.g. 20250301T140509Z.db.
#pragma once

#include <string>

namespace accelcal {

// The default directory (not created). Throws accelcal::Error when neither XDG_DATA_HOME nor
// HOME is set.
std::string DefaultSessionDir();
// A new, unused path in the default directory (created when missing), named by the current UTC
// time ("-2", "-3", ... appended when two sessions start in the same second).
std::string NewSessionPath();
// A session named on the command line: an existing path, or a name (with or without ".db") in
// the default directory. Throws accelcal::Error "no session NAME (looked in ...)" when neither
// exists.
std::string ResolveSessionPath(const std::string& path_or_name);

}  // namespace accelcal
