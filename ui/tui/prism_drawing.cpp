#include "tui/prism_drawing.h"

#include <cmath>

#include <fmt/core.h>

namespace accelcal::ui {

namespace {

constexpr char kAxes[] = {'X', 'Y', 'Z'};

std::string Signed(double component, int axis) {
  return std::string(component >= 0 ? "+" : "-") + kAxes[axis];
}

// The box in a parallel projection; the label sits on the top face, centred.
std::vector<std::string> Box(const std::string& label) {
  const std::string top = fmt::format("{:^8}", label.substr(0, 8));
  return {
      "   +--------+",
      "  /" + top + "/|",
      " +--------+ |",
      " |        | +",
      " |        |/",
      " +--------+",
  };
}

// The turntable from above: the spin axis 'o' and the radial axis of the sensor as an arrow.
std::vector<std::string> Table(const std::string& radial) {
  return {
      "   .--------.",
      "  /          \\",
      " |  o---->" + fmt::format("{:<4}", radial.substr(0, 4)) + "|",
      "  \\          /",
      "   '--------'",
  };
}

// The axis named before " radial" in a pose name ("x radial, z up" -> "+X"), else "?".
std::string RadialAxis(const std::string& pose_name) {
  const size_t at = pose_name.find(" radial");
  if (at == std::string::npos || at == 0) return "?";
  const char axis = pose_name[at - 1];
  const bool negative = at >= 2 && pose_name[at - 2] == '-';
  if (axis != 'x' && axis != 'y' && axis != 'z') return "?";
  return std::string(negative ? "-" : "+") + static_cast<char>(axis - 'a' + 'A');
}

}  // namespace

std::string UpLabel(const Eigen::Vector3d& up) {
  const Eigen::Vector3d unit = up.normalized();
  Eigen::Index axis = 0;
  unit.cwiseAbs().maxCoeff(&axis);
  if (std::abs(unit[axis]) > 0.9) return Signed(unit[axis], static_cast<int>(axis));
  std::string label;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(unit[i]) > 0.2) label += Signed(unit[i], i);
  }
  return label;
}

std::vector<std::string> DrawPose(const std::optional<Eigen::Vector3d>& up,
                                  const std::string& pose_name, bool turntable) {
  if (turntable) {
    std::vector<std::string> rows = Table(RadialAxis(pose_name));
    rows.push_back("top view, " + RadialAxis(pose_name) + " out");
    return rows;
  }
  if (!up || !up->allFinite() || up->norm() == 0) return {};
  const std::string label = UpLabel(*up);
  std::vector<std::string> rows = Box(label);
  if (label.size() <= 2) {
    rows.push_back("face up: " + label);
  } else {
    const Eigen::Vector3d u = up->normalized();
    rows.push_back(fmt::format("up ({:+.1f},{:+.1f},{:+.1f})", u.x(), u.y(), u.z()));
  }
  return rows;
}

}  // namespace accelcal::ui
