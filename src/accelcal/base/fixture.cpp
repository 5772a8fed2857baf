#include "accelcal/base/fixture.h"

#include <cmath>
#include <set>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

// True when every entry is 0 or +-1, one non-zero per row and column, and det = +1.
bool IsProperSignedPermutation(const Eigen::Matrix3d& r) {
  for (int i = 0; i < 3; ++i) {
    int nonzero_in_row = 0;
    int nonzero_in_col = 0;
    for (int j = 0; j < 3; ++j) {
      for (double v : {r(i, j), r(j, i)}) {
        if (v != 0.0 && v != 1.0 && v != -1.0) return false;
      }
      nonzero_in_row += r(i, j) != 0.0;
      nonzero_in_col += r(j, i) != 0.0;
    }
    if (nonzero_in_row != 1 || nonzero_in_col != 1) return false;
  }
  return std::abs(r.determinant() - 1.0) < 1e-12;
}

SensorAxis AxisAlong(const Eigen::Vector3d& v) {
  for (SensorAxis a : {SensorAxis::kPlusX, SensorAxis::kMinusX, SensorAxis::kPlusY,
                       SensorAxis::kMinusY, SensorAxis::kPlusZ, SensorAxis::kMinusZ}) {
    if ((SensorAxisVector(a) - v).norm() < 1e-9) return a;
  }
  throw Error("internal: a fixture rotation that is not a signed permutation");
}

}  // namespace

std::string Fixture::Validate() const {
  if (sensors.empty()) return "the fixture has no sensor";
  std::set<std::string> serials;
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    const FixtureSensor& s = sensors[i];
    const std::string which = fmt::format("sensor {}", i + 1);
    if (s.serial.empty()) return which + " has no serial";
    if (!serials.insert(s.serial).second) {
      return fmt::format("{}: serial '{}' is already another sensor's", which, s.serial);
    }
    if (!IsProperSignedPermutation(s.sensor_to_plate)) {
      return which + ": its rotation is not a right-angle turn (a proper signed permutation)";
    }
    if (!s.offset_m.allFinite()) return which + ": its offset is not a finite number";
  }
  if (!std::isnan(placement_u_rad) && !(std::isfinite(placement_u_rad) && placement_u_rad >= 0.0))
    return "its placement uncertainty must be a finite angle >= 0";
  return {};
}

Eigen::Matrix3d SensorToPlate(SensorAxis x_on_plate, SensorAxis y_on_plate) {
  const Eigen::Vector3d x = SensorAxisVector(x_on_plate);
  const Eigen::Vector3d y = SensorAxisVector(y_on_plate);
  if (std::abs(x.dot(y)) > 0.5) {
    throw Error(fmt::format("a sensor's x ({}) and y ({}) must be perpendicular",
                            SensorAxisToString(x_on_plate), SensorAxisToString(y_on_plate)));
  }
  Eigen::Matrix3d r;
  r.col(0) = x;
  r.col(1) = y;
  r.col(2) = x.cross(y);
  return r;
}

SensorAxis SensorAxisOf(const FixtureSensor& sensor, SensorAxis plate_axis) {
  return AxisAlong(sensor.sensor_to_plate.transpose() * SensorAxisVector(plate_axis));
}

Eigen::Vector3d SensorDirection(const FixtureSensor& sensor, const Eigen::Vector3d& on_plate) {
  return sensor.sensor_to_plate.transpose() * on_plate;
}

double SensorRadiusM(const FixtureSensor& sensor, double plate_radius_m, SensorAxis plate_radial,
                     SensorAxis plate_up) {
  // Plate -> table: the radial to table x, the up to table z (the table's y completes them).
  const Eigen::Vector3d radial = SensorAxisVector(plate_radial);
  const Eigen::Vector3d up = SensorAxisVector(plate_up);
  const Eigen::Vector3d tangential = up.cross(radial);
  const Eigen::Vector2d horizontal(plate_radius_m + radial.dot(sensor.offset_m),
                                   tangential.dot(sensor.offset_m));
  return horizontal.norm();
}

double SensorRadiusPerTurnM(const FixtureSensor& sensor, double plate_radius_m,
                            SensorAxis plate_radial, SensorAxis plate_up) {
  // In the table's frame: the radial x, the tangential y, the up z (as SensorRadiusM).
  const Eigen::Vector3d radial = SensorAxisVector(plate_radial);
  const Eigen::Vector3d up = SensorAxisVector(plate_up);
  const Eigen::Vector3d tangential = up.cross(radial);
  const Eigen::Vector3d offset_table(radial.dot(sensor.offset_m), tangential.dot(sensor.offset_m),
                                     up.dot(sensor.offset_m));
  const Eigen::Vector3d position(plate_radius_m + offset_table.x(), offset_table.y(), 0.0);
  const double radius_m = position.norm();
  // On the spin axis the radius has no first-order change (any direction is outward): its
  // change is |dtheta x o|'s horizontal part, at most |o| per radian.
  if (!(radius_m > 1e-9)) return offset_table.norm();
  return offset_table.cross(position / radius_m).norm();
}

double Fixture::PlacementURad() const {
  return std::isfinite(placement_u_rad) ? placement_u_rad : kUnstatedPlacementURad;
}

Fixture SingleSensorFixture(const std::string& serial) {
  Fixture f;
  f.sensors.push_back(FixtureSensor{serial, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), {}});
  return f;
}

}  // namespace accelcal
