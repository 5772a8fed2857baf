#include "accelcal/app/wizard/pose_setting.h"

#include <cmath>
#include <vector>

#include <fmt/core.h>
#include <fmt/format.h>

namespace accelcal {
namespace {

constexpr char kAxes[] = {'X', 'Y', 'Z'};
constexpr double kLeansUp = 0.2;  // a component above this fraction of |up| leans that face up

// The signed faces of the clearly non-zero components; `flip` names the opposite ones.
std::vector<std::string> Faces(const Eigen::Vector3d& up, bool flip) {
  std::vector<std::string> faces;
  const Eigen::Vector3d u = up.normalized();
  for (int i = 0; i < 3; ++i)
    if (std::abs(u[i]) > kLeansUp) faces.push_back(std::string((u[i] > 0) != flip ? "+" : "-") + kAxes[i]);
  return faces;
}

std::string Joined(const std::vector<std::string>& faces) { return fmt::format("{}", fmt::join(faces, "")); }

// "-X and -Z", "-X, -Y and -Z".
std::string Listed(const std::vector<std::string>& faces) {
  std::string out;
  for (size_t i = 0; i < faces.size(); ++i) {
    if (i > 0) out += i + 1 == faces.size() ? " and " : ", ";
    out += faces[i];
  }
  return out;
}

// The tilt of each leaning face from level: the angle between its normal and the vertical, deg.
std::string Tilts(const Eigen::Vector3d& up, const std::vector<std::string>& faces) {
  const Eigen::Vector3d u = up.normalized();
  std::vector<double> deg;
  for (int i = 0; i < 3; ++i)
    if (std::abs(u[i]) > kLeansUp) deg.push_back(std::acos(std::abs(u[i])) * 180.0 / M_PI);
  bool equal = true;
  for (double d : deg) equal = equal && std::abs(d - deg.front()) < 0.05;
  if (equal) return fmt::format("the {} faces each tilted {:.1f} deg from level", Listed(faces), deg.front());
  std::vector<std::string> each;
  for (size_t i = 0; i < faces.size(); ++i) each.push_back(fmt::format("{} {:.1f} deg", faces[i], deg[i]));
  return fmt::format("the faces tilted from level by {}", fmt::join(each, ", "));
}

}  // namespace

std::string UpFaces(const Eigen::Vector3d& up) { return Joined(Faces(up, false)); }
std::string DownFaces(const Eigen::Vector3d& up) { return Joined(Faces(up, true)); }

bool IsTiltedPose(const Eigen::Vector3d& up) {
  return up.allFinite() && up.norm() > 0 && Faces(up, false).size() > 1;
}

std::string PrismSetting(const Eigen::Vector3d& up, const std::string& pose_name) {
  if (!IsTiltedPose(up)) return "with " + pose_name;
  const std::vector<std::string> up_faces = Faces(up, false);
  const std::vector<std::string> down_faces = Faces(up, true);
  const char* part = up_faces.size() == 2 ? "edge" : "corner";
  return fmt::format("on its {} {} (where the {} faces meet), the {} {} straight above it: {}; "
                     "steady it in a holder",
                     Joined(down_faces), part, Listed(down_faces), Joined(up_faces), part,
                     Tilts(up, up_faces));
}

}  // namespace accelcal
