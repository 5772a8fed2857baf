#include "accelcal/app/device/vehicle_calibration.h"

#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "accelcal/acquire/mavlink/sensor_orientation.h"
#include "accelcal/base/error.h"

namespace accelcal {
namespace {

constexpr const char* kAxisLetters[3] = {"X", "Y", "Z"};

std::string Vector(const VehicleAccelParams& p, const std::array<std::string, 3>& names, const char* unit) {
  std::array<std::string, 3> v;
  for (size_t j = 0; j < 3; ++j) {
    const std::optional<double> x = p.Number(names[j]);
    v[j] = x ? fmt::format("{:.6g}", *x) : "?";
  }
  return fmt::format("x {}, y {}, z {}{}", v[0], v[1], v[2], unit);
}

// "INS_ACCOFFS_X" -> "INS_ACCOFFS", "CAL_ACC0_XOFF" -> "CAL_ACC0_?OFF".
std::string Family(const std::string& x_name) {
  if (x_name.size() > 2 && x_name.compare(x_name.size() - 2, 2, "_X") == 0) return x_name.substr(0, x_name.size() - 2);
  std::string family = x_name;
  const size_t x = family.rfind("_X");
  if (x != std::string::npos) family[x + 1] = '?';
  return family;
}

}  // namespace

FlightStack StackOf(std::uint8_t autopilot) {
  if (autopilot == mavlink::kAutopilotArduPilot) return FlightStack::kArduPilot;
  if (autopilot == mavlink::kAutopilotPx4) return FlightStack::kPx4;
  return FlightStack::kUnknown;
}

std::string StackName(FlightStack stack) {
  switch (stack) {
    case FlightStack::kArduPilot: return "ArduPilot";
    case FlightStack::kPx4: return "PX4";
    case FlightStack::kUnknown: break;
  }
  return "an unknown autopilot";
}

std::vector<std::string> AccelParamNames::All() const {
  std::vector<std::string> all(offset.begin(), offset.end());
  all.insert(all.end(), scale.begin(), scale.end());
  for (const std::string* n : {&device_id, &sensor_rotation, &board_rotation, &thermal})
    if (!n->empty()) all.push_back(*n);
  for (const std::string& n : board_offset_deg)
    if (!n.empty()) all.push_back(n);
  return all;
}

AccelParamNames AccelParamNamesFor(FlightStack stack, int imu) {
  if (imu < 0 || imu > 2) throw Error(fmt::format("IMU {}: the autopilots hold calibrations for IMUs 0, 1 and 2", imu));
  AccelParamNames n;
  if (stack == FlightStack::kArduPilot) {
    const std::string prefix = imu == 0 ? "INS_ACC" : fmt::format("INS_ACC{}", imu + 1);
    for (int j = 0; j < 3; ++j) {
      n.offset[static_cast<size_t>(j)] = fmt::format("{}OFFS_{}", prefix, kAxisLetters[j]);
      n.scale[static_cast<size_t>(j)] = fmt::format("{}SCAL_{}", prefix, kAxisLetters[j]);
    }
    n.device_id = imu == 0 ? "INS_ACC_ID" : fmt::format("INS_ACC{}_ID", imu + 1);
    n.board_rotation = "AHRS_ORIENTATION";
    n.thermal = fmt::format("INS_TCAL{}_ENABLE", imu + 1);
    return n;
  }
  if (stack == FlightStack::kPx4) {
    for (int j = 0; j < 3; ++j) {
      n.offset[static_cast<size_t>(j)] = fmt::format("CAL_ACC{}_{}OFF", imu, kAxisLetters[j]);
      n.scale[static_cast<size_t>(j)] = fmt::format("CAL_ACC{}_{}SCALE", imu, kAxisLetters[j]);
      n.board_offset_deg[static_cast<size_t>(j)] = fmt::format("SENS_BOARD_{}_OFF", kAxisLetters[j]);
    }
    n.device_id = fmt::format("CAL_ACC{}_ID", imu);
    n.sensor_rotation = fmt::format("CAL_ACC{}_ROT", imu);
    n.board_rotation = "SENS_BOARD_ROT";
    n.thermal = "TC_A_ENABLE";
    return n;
  }
  throw Error("the vehicle's autopilot is neither ArduPilot nor PX4: its accelerometer parameters are unknown");
}

std::optional<double> VehicleAccelParams::Number(const std::string& name) const {
  const auto it = values.find(name);
  if (it == values.end()) return std::nullopt;
  return mavlink::ParamNumber(it->second, stack == FlightStack::kPx4);
}

VehicleAccelParams ReadVehicleAccelParams(mavlink::Connection& link, int imu,
                                          const mavlink::ParamExchange& exchange) {
  mavlink::AwaitVehicle(link, exchange);
  VehicleAccelParams p;
  p.stack = StackOf(link.vehicle().autopilot);
  p.imu = imu;
  p.vehicle = link.vehicle().Describe();
  p.link = link.LinkName();
  p.names = AccelParamNamesFor(p.stack, imu);
  mavlink::ParamReadResult read = mavlink::ReadParams(link, p.names.All(), exchange);
  p.values = std::move(read.values);
  p.unanswered = std::move(read.unanswered);
  return p;
}

std::vector<std::string> DescribeVehicleAccelParams(const VehicleAccelParams& p) {
  std::vector<std::string> lines;
  lines.push_back(fmt::format("{} on {}, IMU {}: its own accelerometer calibration", p.vehicle, p.link, p.imu));
  if (p.values.empty()) {
    lines.push_back(fmt::format("the vehicle answered none of the {} PARAM_REQUEST_READ ({}, ...): its "
                                "calibration is unknown", p.unanswered.size(),
                                p.unanswered.empty() ? "" : p.unanswered.front()));
    return lines;
  }
  lines.push_back(fmt::format("{}: {}", Family(p.names.offset[0]), Vector(p, p.names.offset, " m/s^2")));
  lines.push_back(fmt::format("{}: {}", Family(p.names.scale[0]), Vector(p, p.names.scale, "")));
  if (const std::optional<double> id = p.Number(p.names.device_id))
    lines.push_back(fmt::format("{} {:.0f} (the sensor's device id on the autopilot)", p.names.device_id, *id));
  for (const std::string* name : {&p.names.sensor_rotation, &p.names.board_rotation}) {
    if (name->empty()) continue;
    const std::optional<double> v = p.Number(*name);
    if (!v) continue;
    const std::optional<mavlink::SensorOrientation> o = mavlink::FindSensorOrientation(static_cast<int>(*v));
    lines.push_back(fmt::format("{} {:.0f} ({})", *name, *v,
                                *v < 0 ? "internal: the board's rotation applies"
                                : o    ? o->name : "not in accelcal's table of rotations"));
  }
  if (!p.names.board_offset_deg[0].empty())
    lines.push_back(fmt::format("SENS_BOARD_?_OFF: {}", Vector(p, p.names.board_offset_deg, " deg")));
  if (const std::optional<double> t = p.Number(p.names.thermal))
    lines.push_back(fmt::format("{} {:.0f} ({})", p.names.thermal, *t,
                                *t != 0.0 ? "a temperature calibration corrects the readings" : "no temperature calibration"));
  if (!p.unanswered.empty())
    lines.push_back(fmt::format("not answered: {}", fmt::join(p.unanswered, ", ")));
  return lines;
}

std::optional<mavlink::AccelUndo> UndoOf(const VehicleAccelParams& p, std::string* why) {
  auto refuse = [&](std::string text) -> std::optional<mavlink::AccelUndo> {
    *why = std::move(text);
    return std::nullopt;
  };
  mavlink::AccelUndo undo;
  for (size_t j = 0; j < 3; ++j) {
    const std::optional<double> off = p.Number(p.names.offset[j]);
    const std::optional<double> scale = p.Number(p.names.scale[j]);
    if (!off || !scale)
      return refuse(fmt::format("the vehicle did not answer for {}", !off ? p.names.offset[j] : p.names.scale[j]));
    if (!(*scale > 0.0) || !std::isfinite(*off))
      return refuse(fmt::format("{} = {:g} cannot be undone (not a positive scale)", p.names.scale[j], *scale));
    undo.offset_mps2(static_cast<Eigen::Index>(j)) = *off;
    undo.scale(static_cast<Eigen::Index>(j)) = *scale;
  }
  if (const std::optional<double> t = p.Number(p.names.thermal); t && *t != 0.0)
    return refuse(fmt::format("{} is on: the vehicle corrects its readings for temperature by its own "
                              "polynomial, which accelcal does not undo; set it to 0 for the calibration",
                              p.names.thermal));
  for (const std::string& n : p.names.board_offset_deg)
    if (const std::optional<double> v = n.empty() ? std::nullopt : p.Number(n); v && *v != 0.0)
      return refuse(fmt::format("{} = {:g} deg: a board offset angle is not undone here; set it to 0 "
                                "for the calibration", n, *v));
  std::string rotation_name = p.names.board_rotation;
  std::optional<double> rotation = p.Number(p.names.board_rotation);
  if (!p.names.sensor_rotation.empty())
    if (const std::optional<double> own = p.Number(p.names.sensor_rotation); own && *own >= 0.0) {
      rotation = own;
      rotation_name = p.names.sensor_rotation;
    }
  if (!rotation) return refuse(fmt::format("the vehicle did not answer for {}", rotation_name));
  const std::optional<mavlink::SensorOrientation> o = mavlink::FindSensorOrientation(static_cast<int>(*rotation));
  if (!o)
    return refuse(fmt::format("{} = {:.0f} is a rotation accelcal cannot undo; set it to 0 (none) for "
                              "the calibration", rotation_name, *rotation));
  undo.body_from_sensor = o->BodyFromSensor();
  undo.description = fmt::format("{} ({:.6g}, {:.6g}, {:.6g}) m/s^2, {} ({:.6g}, {:.6g}, {:.6g}), {} {} ({})",
                                 Family(p.names.offset[0]), undo.offset_mps2.x(), undo.offset_mps2.y(),
                                 undo.offset_mps2.z(), Family(p.names.scale[0]), undo.scale.x(),
                                 undo.scale.y(), undo.scale.z(), rotation_name, o->value, o->name);
  return undo;
}

std::vector<ParamWrite> ResetWrites(const VehicleAccelParams& p) {
  std::vector<ParamWrite> writes;
  for (const std::string& n : p.names.offset) writes.push_back({n, 0.0, mavlink::kParamTypeReal32});
  for (const std::string& n : p.names.scale) writes.push_back({n, 1.0, mavlink::kParamTypeReal32});
  if (const std::optional<double> t = p.Number(p.names.thermal); t && *t != 0.0)
    writes.push_back({p.names.thermal, 0.0, p.values.at(p.names.thermal).type});
  return writes;
}

}  // namespace accelcal
