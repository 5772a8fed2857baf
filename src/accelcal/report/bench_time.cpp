#include "accelcal/report/bench_time.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include <fmt/core.h>

#include "accelcal/base/sensor_model.h"

namespace accelcal {
namespace {

double NumberAt(const std::map<std::string, std::string>& values, const char* key) {
  const auto it = values.find(key);
  if (it == values.end()) return kNaN;
  char* end = nullptr;
  const double v = std::strtod(it->second.c_str(), &end);
  return end != it->second.c_str() ? v : kNaN;
}

std::vector<double> NumbersAt(const std::map<std::string, std::string>& values, const char* key) {
  std::vector<double> out;
  const auto it = values.find(key);
  if (it == values.end()) return out;
  std::istringstream in(it->second);
  std::string word;
  while (in >> word) out.push_back(std::strtod(word.c_str(), nullptr));  // "nan" reads as NaN
  return out;
}

std::string BenchSecondsText(double s) {
  if (s < 120.0) return fmt::format("{:.0f} s", s);
  return fmt::format("{:.0f} min {:02.0f} s", std::floor(s / 60.0), std::fmod(s, 60.0));
}

// A parameter's U in its unit (misalignment in mrad), and the unit's name.
std::string UText(int index, double u) {
  if (!std::isfinite(u)) return "-";
  return fmt::format("{:.3g}", index >= kMisYZ ? u * 1e3 : u);
}
const char* UUnit(int index) {
  return index >= kMisYZ ? "mrad" : index >= kScaleX ? "counts/(m/s^2)" : "counts";
}

}  // namespace

std::optional<ReportBenchTime> BenchTimeFromInputs(const SessionInputs& inputs) {
  const auto plan = inputs.find(kBenchPlanStepId);
  if (plan == inputs.end()) return std::nullopt;
  ReportBenchTime b;
  const auto by = plan->second.find(bench_key::kPlannedBy);
  b.planned_by = by == plan->second.end() ? "" : by->second;
  b.planned.capture_s = NumberAt(plan->second, bench_key::kPlannedCaptureS);
  b.planned.settle_s = NumberAt(plan->second, bench_key::kPlannedSettleS);
  b.planned.handling_s = NumberAt(plan->second, bench_key::kPlannedHandlingS);
  const std::vector<double> planned_u = NumbersAt(plan->second, bench_key::kPlannedU);
  const std::vector<double> target_u = NumbersAt(plan->second, bench_key::kTargetU);
  for (int j = 0; j < kNumBaseParameters; ++j) {
    BenchParameterU p;
    p.name = std::string(ParameterName(j));
    const size_t i = static_cast<size_t>(j);
    if (i < planned_u.size()) p.planned = planned_u[i];
    if (i < target_u.size()) p.target = target_u[i];
    b.parameters.push_back(p);
  }
  for (const auto& [step, values] : inputs) {
    const double capture_s = NumberAt(values, bench_key::kCaptureS);
    if (!std::isfinite(capture_s)) continue;
    ++b.captures;
    b.spent.capture_s += capture_s;
    if (const double s = NumberAt(values, bench_key::kSettleS); std::isfinite(s)) b.spent.settle_s += s;
    if (const double s = NumberAt(values, bench_key::kHandlingS); std::isfinite(s)) b.spent.handling_s += s;
  }
  return b;
}

void FillReachedU(const UncertaintyBudget& budget, ReportBenchTime* bench) {
  for (const ParameterBudget& p : budget.parameters)
    if (p.index >= 0 && static_cast<size_t>(p.index) < bench->parameters.size())
      bench->parameters[static_cast<size_t>(p.index)].reached = p.expanded;
}

std::vector<std::string> BenchTimeLines(const ReportBenchTime& b) {
  std::vector<std::string> lines;
  lines.push_back(fmt::format("Bench time: {} spent on {} captures (planned {}, {}): capture {}, settling {}, "
                              "handling {}",
                              BenchSecondsText(b.spent.TotalS()), b.captures, BenchSecondsText(b.planned.TotalS()),
                              b.planned_by == "target" ? "by the procedure's target" : "fixed capture lengths",
                              BenchSecondsText(b.spent.capture_s), BenchSecondsText(b.spent.settle_s), BenchSecondsText(b.spent.handling_s)));
  for (size_t j = 0; j < b.parameters.size(); ++j) {
    const BenchParameterU& p = b.parameters[j];
    if (!std::isfinite(p.planned) && !std::isfinite(p.reached)) continue;
    const int index = static_cast<int>(j);
    if (lines.size() == 1) lines.push_back(fmt::format("{:<8} {:>9} {:>9} {:>9}  U (k=2)", "", "planned", "reached", "target"));
    lines.push_back(fmt::format("{:<8} {:>9} {:>9} {:>9}  {}", p.name, UText(index, p.planned), UText(index, p.reached),
                                UText(index, p.target), UUnit(index)));
  }
  return lines;
}

}  // namespace accelcal
