#include "tui/sensor_blocks.h"

#include <algorithm>
#include <string>

#include <fmt/core.h>

#include "tui/text_util.h"

namespace accelcal::ui {
namespace {

bool OnTurntable(const WizardView& view) {
  return view.screen == WizardScreen::kMountTurntable || view.pose_name.find("radial") != std::string::npos;
}

std::string Cell(const SensorStatus& s) {
  return Asciify(s.ok ? s.name + " ok" : s.name + " ! " + s.state);
}

std::vector<Line> Grid(const std::vector<SensorStatus>& sensors, int width) {
  size_t cell_width = 0;
  for (const SensorStatus& s : sensors) cell_width = std::max(cell_width, Cell(s).size() + 2);
  const int columns = std::max(1, width / static_cast<int>(std::max<size_t>(cell_width, 1)));
  std::vector<Line> rows;
  for (size_t i = 0; i < sensors.size(); i += static_cast<size_t>(columns)) {
    Line row;
    for (size_t k = i; k < std::min(sensors.size(), i + static_cast<size_t>(columns)); ++k) {
      std::string text = Cell(sensors[k]);
      text.resize(cell_width, ' ');
      row.push_back({text, sensors[k].ok ? Role::kPass : Role::kWarn});
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<Line> Details(const std::vector<SensorStatus>& sensors, int width) {
  std::vector<const SensorStatus*> order;
  for (const SensorStatus& s : sensors)
    if (!s.ok) order.push_back(&s);
  for (const SensorStatus& s : sensors)
    if (s.ok) order.push_back(&s);
  std::vector<Line> rows;
  for (const SensorStatus* s : order) {
    const std::string text = fmt::format("{:<6} {}: {}", s->name, s->state, s->detail);
    rows.push_back({{Clip(Asciify(text), width), s->ok ? Role::kNormal : Role::kWarn}});
  }
  return rows;
}

}  // namespace

std::vector<Line> SensorsBlock(const WizardView& view, const RenderState& state, int width) {
  if (view.sensors.size() < 2) return {};
  const long ok = std::count_if(view.sensors.begin(), view.sensors.end(),
                                [](const SensorStatus& s) { return s.ok; });
  std::vector<Line> rows;
  rows.push_back({{"sensors  ", Role::kDim},
                  {fmt::format("{} of {} {}{}", ok, view.sensors.size(),
                               OnTurntable(view) ? "delivering" : "still and in their pose",
                               state.details ? "" : " (d: each one's figures)"),
                   ok == static_cast<long>(view.sensors.size()) ? Role::kPass : Role::kWarn}});
  std::vector<Line> more = state.details ? Details(view.sensors, width) : Grid(view.sensors, width);
  rows.insert(rows.end(), more.begin(), more.end());
  return rows;
}

}  // namespace accelcal::ui
