// The small ASCII drawing of where the sensor must be: a prism (a box) with the face that must
// be up named on its top; for a tilted pose the prism seen from the side standing on the edge or
// corner that goes down, named with the one straight above it; or the turntable seen from above
// with the radial axis as an arrow.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace accelcal::ui {

inline constexpr int kDrawingWidth = 20;

// The rows of the drawing (each at most kDrawingWidth characters), ending with a caption;
// empty when there is nothing to draw (no pose asked).
// `up`: the expected up direction in the sensor frame; `pose_name`: e.g. "+z up",
// "x radial, z up"; `turntable`: draw the turntable instead of the prism.
std::vector<std::string> DrawPose(const std::optional<Eigen::Vector3d>& up,
                                  const std::string& pose_name, bool turntable);

// "+Z", "-X" for an up vector along an axis (within about 25 degrees); for a tilted one the
// signs of its clearly non-zero components, e.g. "+X+Y-Z".
std::string UpLabel(const Eigen::Vector3d& up);

}  // namespace accelcal::ui
