// How to set the prism for a pose, in plain words, from the pose's "up" direction in the sensor
// frame: a face up ("with +z up"), or, for a tilted pose, the edge or corner it stands on and
// how far each face leans ("on its -X-Y-Z corner, where the -X, -Y and -Z faces meet ...").
#pragma once

#include <string>

#include <Eigen/Core>

namespace accelcal {

// The faces that lean up in `up` (unit or not): the signed axes whose component is clearly
// non-zero (|u_i| > 0.2 of the norm), e.g. "+X+Y+Z"; one face for a face-up pose.
std::string UpFaces(const Eigen::Vector3d& up);
// The opposite faces (the ones towards the table), e.g. "-X-Y-Z".
std::string DownFaces(const Eigen::Vector3d& up);

// The placing instruction, to follow "Put the prism on the table " / "Set the prism ":
//   face up:  "with +z up" (pose_name as given);
//   an edge:  "on its -X-Z edge (where the -X and -Z faces meet), the +X+Z edge straight above
//             it: the +X and +Z faces each tilted 45 deg from level; steady it in a holder";
//   a corner: "on its -X-Y-Z corner (where the -X, -Y and -Z faces meet), the +X+Y+Z corner
//             straight above it: the +X, +Y and +Z faces each tilted 54.7 deg from level; ...".
// Unequal tilts are named face by face ("+X 35.3 deg, +Y 65.9 deg").
std::string PrismSetting(const Eigen::Vector3d& up, const std::string& pose_name);

// True when `up` is a tilted pose (more than one face leans up).
bool IsTiltedPose(const Eigen::Vector3d& up);

}  // namespace accelcal
