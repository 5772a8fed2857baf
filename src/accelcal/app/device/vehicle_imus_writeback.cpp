#include "accelcal/app/device/vehicle_imus_writeback.h"

#include <fmt/format.h>

#include "accelcal/app/device/vehicle_writeback.h"

namespace accelcal {
namespace {

// A word as a POSIX shell reads it back: as it is when it is plain, else single-quoted.
std::string ShellWord(const std::string& word) {
  const bool plain = !word.empty() && word.find_first_not_of(
                                          "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                          "0123456789_./:,=@+-") == std::string::npos;
  if (plain) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

std::vector<std::string> ImuWritebackLines(const std::string& session_path, const MavlinkSourceSpec& link,
                                           const std::string& procedure_path,
                                           const std::vector<ImuWriteback>& imus) {
  std::vector<std::string> lines;
  lines.push_back("Each IMU's calibration goes into the vehicle on its own, while it is on the link (each "
                  "PARAM_SET echoed and read back; without --apply the command only shows them):");
  for (const ImuWriteback& one : imus) {
    MavlinkSourceSpec target = link;
    target.imu = one.imu;
    if (!one.calibration) {
      lines.push_back(fmt::format("  IMU {} ({}): nothing to write: {}", one.imu, one.serial,
                                  one.reason.empty() ? "no calibration" : one.reason));
      continue;
    }
    if (!one.undone) {
      lines.push_back(fmt::format(
          "  IMU {} ({}): nothing to write: the vehicle's own calibration was left in its readings "
          "(--vehicle-calibration as-is), so this calibration describes the IMU after it and written as "
          "its offsets and scales would be wrong; reset it (accelcal device-info --source {} --reset "
          "--apply) and calibrate again",
          one.imu, one.serial, target.Describe()));
      continue;
    }
    std::string command = fmt::format("accelcal export-cal {} --sensor {} --to {}", ShellWord(session_path),
                                      one.sensor, ShellWord(target.Describe()));
    if (!DriverScaleOfUnit(one.calibration->reading_unit))  // counts: the procedure's scaling
      command += " --procedure " + ShellWord(procedure_path);
    const std::string verdict = one.verdict == "PASS" ? one.verdict
                                                      : one.verdict + ": read its report before writing it";
    lines.push_back(fmt::format("  IMU {} ({}, {}): {} --apply", one.imu, one.serial, verdict, command));
  }
  return lines;
}

}  // namespace accelcal
