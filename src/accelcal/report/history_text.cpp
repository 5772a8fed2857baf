#include "accelcal/report/history_text.h"

#include <cmath>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "accelcal/base/sensor_model.h"
#include "accelcal/base/utc_time.h"

namespace accelcal {

std::string FormatHistoryText(const DeviceHistory& h) {
  std::string t = fmt::format("device {}: {} calibration(s) in {}", h.device, h.entries.size(), h.dir);
  if (h.sessions_without_result > 0)
    t += fmt::format(" ({} session(s) without a calibration not shown)", h.sessions_without_result);
  t += fmt::format("\nmoves are since the previous calibration, in units and in sigmas of the combined "
                   "1-sigma; over {} sigmas: changed\n", kChangedSigmas);
  for (const HistoryEntry& e : h.entries) {
    t += fmt::format("\n{} UTC  session {}\n", ShortUtc(e.session.created_utc), e.session.name);
    t += fmt::format("  {:<9} {:>16} {:>12} {:>14} {:>9}  {}\n", "parameter", "value", "1-sigma", "moved",
                     "sigmas", "unit");
    const auto p = e.calibration.model.ToVector(), s = e.calibration.uncertainty.ToVector();
    std::vector<std::string> changed;
    for (int i = 0; i < kNumBaseParameters; ++i) {
      std::string moved = "-", sigmas = "-", flag;
      if (!e.moves.empty()) {
        const ParameterMove& m = e.moves[static_cast<size_t>(i)];
        moved = fmt::format("{:+.6g}", m.delta);
        sigmas = std::isfinite(m.n_sigmas) ? fmt::format("{:.1f}", m.n_sigmas) : "inf";
        if (m.changed) {
          flag = "  changed";
          changed.emplace_back(ParameterName(i));
        }
      }
      t += fmt::format("  {:<9} {:>16.10g} {:>12.3g} {:>14} {:>9}  {}{}\n", ParameterName(i), p(i), s(i),
                       moved, sigmas, ParameterUnit(i), flag);
    }
    if (!e.moves.empty())
      t += changed.empty() ? std::string("  no parameter changed beyond its uncertainty\n")
                           : fmt::format("  changed: {}\n", fmt::join(changed, ", "));
  }
  return t;
}

}  // namespace accelcal
