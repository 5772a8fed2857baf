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

// A tilted pose: the prism seen from the side standing on the edge (two faces lean up) or the
// corner (three) named `down`, the opposite edge or corner `up` straight above it.
std::vector<std::string> OnEdge(const std::string& up, const std::string& down) {
  return {
      fmt::format("{:^19}", up + " up"),
      "         +",
      "        / \\",
      "       +   +",
      "        \\ /",
      "  ~~~~~~~+~~~~~~~~",
      "edge " + down + " down",
  };
}

std::vector<std::string> OnCorner(const std::string& up, const std::string& down) {
  return {
      fmt::format("{:^19}", up + " up"),
      "         +",
      "      .-'|'-.",
      "     +   |   +",
      "     |'-.+.-'|",
      "     +   |   +",
      "      '-.|.-'",
      "  ~~~~~~~+~~~~~~~~",
      "corner " + down + " down",
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
  if (label.size() > 2) {
    const std::string down = UpLabel(-*up);
    return label.size() == 4 ? OnEdge(label, down) : OnCorner(label, down);
  }
  std::vector<std::string> rows = Box(label);
  rows.push_back("face up: " + label);
  return rows;
}

}  // namespace accelcal::ui
