// A calibration given to a command, from a calibration file or from a wizard session: the one
// rule that tells the two apart and the one set of errors, for every command that takes either
// (`report`, `export-cal`, `allan --calibration`) or a session only (`refit`), and the one test
// of "is this a session file?" (also `allan`'s, whose input is a recording or a session).
//
// The rule, on what `input` names:
//   - something read once (a pipe, `-`, a character device): a calibration file's text (a
//     session needs a file SQLite can seek in, and the bytes sniffed would be gone);
//   - a file that starts with SQLite's header: a session;
//   - a file whose first non-blank byte is '{': a calibration file (JSON; a session's result,
//     as `report --format calibration` writes it, is one too);
//   - any other file: neither (Error "PATH is not an accelcal session or a calibration file ...");
//   - nothing: a bare name is a session's name in the default session folder
//     (session_paths.h: Error "no session NAME (looked in DIR and the current directory)"); a
//     path is a missing file (Error "cannot open 'PATH': No such file or directory").
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "accelcal/calibration/calibration.h"
#include "accelcal/session/session_store.h"

namespace accelcal {

// True when `path` is a regular file that starts with SQLite's 16-byte header (never for a pipe,
// a device or "-": nothing is read from them).
bool IsSessionFile(const std::string& path);

enum class CalibrationInputKind { kCalibrationFile, kSession };

// What `input` names, by the rule above; `path` is the file to read (a session's name resolved to
// its file). Throws accelcal::Error when it names neither, or nothing.
struct LocatedCalibrationInput {
  CalibrationInputKind kind = CalibrationInputKind::kCalibrationFile;
  std::string path;
};
LocatedCalibrationInput LocateCalibrationInput(const std::string& input);

// A session opened read-only for the calibration it holds. Throws accelcal::Error naming the
// session when it has none: "session PATH has no calibration: it holds records (...), which
// another command analyses" (a drift or noise session), else "session PATH has no calibration
// yet: N captures accepted; run the wizard to finish it".
struct SessionWithResult {
  std::unique_ptr<SessionStore> store;
  SessionInfo info;
  std::string result_text;  // the calibration file's JSON, with the session's gaps beside it
};
// `sensor`: which of a several-sensor session's sensors (0: the first, a one-sensor session's
// only; Error naming the count when the session has no such sensor).
SessionWithResult OpenSessionResult(const std::string& path, int sensor = 0);

// The calibration of `input` and what is known of its origin.
struct CalibrationInput {
  CalibrationInputKind kind = CalibrationInputKind::kCalibrationFile;
  std::string path;                    // what was read
  std::string text;                    // the calibration file's text, or the session's result
  Calibration calibration;             // strictly read (InputError naming the file or session)
  std::optional<SessionInfo> session;  // from a session: its device, operator, dates, procedure
};
CalibrationInput ReadCalibrationInput(const std::string& input, int sensor = 0);
CalibrationInput ReadCalibrationInput(const LocatedCalibrationInput& at, int sensor = 0);

// The session `input` names, by the rule above, opened for writing (its lock held) to change its
// calibration (`refit`). Throws accelcal::Error for a calibration file ("PATH is a calibration
// file, not a session: ..."; a refit needs the session's captures), for a file that is neither,
// and for nothing there (ResolveSessionPath's "no session NAME ...").
std::unique_ptr<SessionStore> OpenSessionToChange(const std::string& input);

}  // namespace accelcal
