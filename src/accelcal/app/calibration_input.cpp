#include "accelcal/app/calibration_input.h"

#include <sys/stat.h>

#include <fstream>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/io/text_file.h"
#include "accelcal/session/session_paths.h"

namespace accelcal {

namespace {

bool IsRegularFile(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

// A calibration file is JSON: its first non-blank byte is '{'.
bool StartsLikeJson(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char c = 0;
  while (in.get(c))
    if (c != ' ' && c != '\n' && c != '\r' && c != '\t') return c == '{';
  return false;
}

}  // namespace

bool IsSessionFile(const std::string& path) {
  if (!IsRegularFile(path)) return false;
  std::ifstream in(path, std::ios::binary);
  char magic[16] = {};
  in.read(magic, sizeof magic);
  return in.gcount() == sizeof magic && std::string(magic, sizeof magic) == std::string("SQLite format 3\0", 16);
}

LocatedCalibrationInput LocateCalibrationInput(const std::string& input) {
  if (IsReadOnceInput(input)) return {CalibrationInputKind::kCalibrationFile, input};
  if (IsSessionFile(input)) return {CalibrationInputKind::kSession, input};
  if (IsRegularFile(input)) {
    if (StartsLikeJson(input)) return {CalibrationInputKind::kCalibrationFile, input};
    throw Error(fmt::format("{} is not an accelcal session or a calibration file (neither a "
                            "session's SQLite file nor JSON)", input));
  }
  // Nothing there: a bare name is a session's in the default folder; a path is a missing file,
  // said as its reader says it.
  if (input.find('/') == std::string::npos) return {CalibrationInputKind::kSession, ResolveSessionPath(input)};
  return {CalibrationInputKind::kCalibrationFile, input};
}

SessionWithResult OpenSessionResult(const std::string& path, int sensor) {
  SessionOpenOptions read_only;
  read_only.read_only = true;
  SessionWithResult s;
  s.store = SessionStore::Open(path, read_only);
  s.info = s.store->Info();
  const Fixture sensors = SessionSensors(*s.store);
  if (sensor < 0 || static_cast<std::size_t>(sensor) >= sensors.sensors.size())
    throw Error(fmt::format("--sensor {}: session {} has {} sensor(s)", sensor + 1, path,
                            sensors.sensors.size()));
  if (s.store->Sensors()) s.info.device = sensors.sensors[static_cast<std::size_t>(sensor)].serial;
  std::optional<std::string> result = s.store->SensorResult(sensor);
  if (!result && sensor > 0)
    throw Error(fmt::format("session {} has no calibration of sensor {} ({}): {} of its captures "
                            "accepted", path, sensor + 1,
                            sensors.sensors[static_cast<std::size_t>(sensor)].serial,
                            s.store->SensorCaptures(sensor).size()));
  if (!result && !DescribeRecords(*s.store).empty())
    throw Error(fmt::format("session {} has no calibration: it holds records ({}), which another "
                            "command analyses", path, DescribeRecords(*s.store)));
  if (!result)
    throw Error(fmt::format("session {} has no calibration yet: {} captures accepted; run the "
                            "wizard to finish it", path, s.info.num_captures));
  s.result_text = std::move(*result);
  return s;
}

CalibrationInput ReadCalibrationInput(const LocatedCalibrationInput& at, int sensor) {
  CalibrationInput in;
  in.kind = at.kind;
  in.path = at.path;
  if (at.kind != CalibrationInputKind::kSession && sensor != 0)
    throw Error(fmt::format("--sensor {}: {} is a calibration file, of one sensor", sensor + 1,
                            at.path));
  if (at.kind == CalibrationInputKind::kSession) {
    SessionWithResult s = OpenSessionResult(at.path, sensor);
    in.text = std::move(s.result_text);
    in.session = std::move(s.info);
  } else {
    in.text = ReadTextFile(at.path);
  }
  in.calibration = CalibrationFromJsonText(in.text, at.path);
  return in;
}

CalibrationInput ReadCalibrationInput(const std::string& input, int sensor) {
  return ReadCalibrationInput(LocateCalibrationInput(input), sensor);
}

std::unique_ptr<SessionStore> OpenSessionToChange(const std::string& input) {
  if (IsRegularFile(input) && !IsSessionFile(input)) {
    LocateCalibrationInput(input);  // throws for a file that is neither
    throw Error(fmt::format("{} is a calibration file, not a session: only a session holds the captures "
                            "to fit again (give the session it came from)", input));
  }
  SessionOpenOptions existing;
  existing.create_if_missing = false;
  return SessionStore::Open(ResolveSessionPath(input), existing);
}

}  // namespace accelcal
