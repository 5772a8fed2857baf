// A fixture: several sensors (devices under test) on one plate, placed on the prism and mounted
// on the turntable as one body, so that each pose is taken once for all of them (issue 31).
//
// Frames: the plate frame is the one a procedure's poses and mountings are written in (for a
// one-sensor session, the sensor's own frame). Each sensor is mounted on the plate turned by a
// right angle or not at all (a board on a fixture sits square to it; what is left is the
// placement error every capture has): its rotation maps its own platform frame into the plate's,
// v_plate = sensor_to_plate v_sensor, and is a signed permutation with determinant +1.
//
// Offsets in m, in the plate frame, from the plate's reference point: the point a procedure's
// turntable radius is measured to. Each sensor's sensing point is elsewhere on the plate, so its
// turntable radius is its own (SensorRadiusM). A plate centred on the spin axis is a procedure
// radius of 0 and each sensor's offset.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"

namespace accelcal {

struct FixtureSensor {
  std::string serial;  // the device's serial number, unique in its fixture
  Eigen::Matrix3d sensor_to_plate = Eigen::Matrix3d::Identity();
  Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();  // sensing point from the reference, m
  // The spec of the sensor's own link (source_spec.h); empty: it is one of the fixture's shared
  // source's sensors, in the order of the fixture's sensors that have none.
  std::string source;
};

struct Fixture {
  std::string name;  // what the lab calls the plate; may be empty
  std::vector<FixtureSensor> sensors;
  // How square the plate is set down on the turntable at each mounting: the standard
  // uncertainty (1-sigma) of each component of the small rotation about its reference point that
  // it is set down with, rad (a clamped jig ~0.1 deg, a plate placed by hand ~0.5 deg). NaN: not
  // stated (PlacementURad then takes a plate placed by hand). It moves every board off the
  // reference point, and so its turntable radius (SensorRadiusPerTurnM).
  double placement_u_rad = kNaN;

  // placement_u_rad, or kUnstatedPlacementURad when it is not stated.
  double PlacementURad() const;

  // Empty when usable; otherwise the first problem found (no sensor, an empty or repeated
  // serial, a rotation that is not a proper signed permutation, an offset not finite).
  std::string Validate() const;
};

// The rotation that takes the sensor's +x to `x_on_plate` and its +y to `y_on_plate` (its +z
// follows, right-handed). Throws accelcal::Error when the two axes are not perpendicular.
Eigen::Matrix3d SensorToPlate(SensorAxis x_on_plate, SensorAxis y_on_plate);

// The plate's axis `plate_axis` as one of the sensor's axes.
SensorAxis SensorAxisOf(const FixtureSensor& sensor, SensorAxis plate_axis);
// A direction given on the plate (a pose's up), in the sensor's frame.
Eigen::Vector3d SensorDirection(const FixtureSensor& sensor, const Eigen::Vector3d& on_plate);

// Distance of the sensor's sensing point from the spin axis, m, when the plate is mounted with
// `plate_radial` outward and `plate_up` along the axis and its reference point at
// plate_radius_m from it: the horizontal part of (plate_radius_m along the radial) + the offset
// turned into the table. An offset along the spin axis changes nothing.
double SensorRadiusM(const FixtureSensor& sensor, double plate_radius_m, SensorAxis plate_radial,
                     SensorAxis plate_up);

// The plate's placement uncertainty taken when the fixture does not state it: a plate set down
// by hand, 0.5 deg per rotation component (the virtual bench's hand-held placement).
inline constexpr double kUnstatedPlacementURad = 0.5 * M_PI / 180.0;

// How much the sensor's turntable radius (SensorRadiusM, same arguments) moves per radian of
// the plate's placement error, m/rad: a small rotation dtheta of the plate about its reference
// point moves the sensing point by dtheta x o (o the offset, on the table), and its radius by
// n . (dtheta x o) = dtheta . (o x n), n the horizontal unit vector from the spin axis to it.
// With each component of dtheta of standard uncertainty u, the radius's is u |o x n|: this
// returns |o x n|. 0 for a sensor at the reference point. An offset along the spin axis counts
// here (the plate tilted moves it sideways) though it does not change the radius itself.
double SensorRadiusPerTurnM(const FixtureSensor& sensor, double plate_radius_m,
                            SensorAxis plate_radial, SensorAxis plate_up);

// The fixture of a one-sensor session: that sensor, square to the plate, at its reference point.
Fixture SingleSensorFixture(const std::string& serial);

}  // namespace accelcal
