#include "accelcal/app/wizard/final_summary.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/core.h>

#include "accelcal/base/sensor_model.h"
#include "accelcal/report/uncertainty_text.h"

namespace accelcal {
namespace {

constexpr size_t kWidth = 78;

// `text` on lines of at most kWidth columns, the first starting with `first`, the others
// indented by its leading blanks plus four.
std::vector<std::string> Wrapped(const std::string& first, const std::string& text) {
  std::vector<std::string> out;
  std::string line = first;
  bool has_word = false;
  std::istringstream words(text);
  for (std::string w; words >> w;) {
    if (has_word && line.size() + 1 + w.size() > kWidth) {
      out.push_back(line);
      line = std::string(first.find_first_not_of(' ') == std::string::npos ? first.size() + 4
                                                                             : first.find_first_not_of(' ') + 4,
                         ' ');
      has_word = false;
    }
    line += (has_word ? " " : "") + w;
    has_word = true;
  }
  if (has_word) out.push_back(line);
  return out;
}

void Add(std::vector<std::string>* lines, const std::vector<std::string>& more) {
  lines->insert(lines->end(), more.begin(), more.end());
}

// "2051.31 +- 0.51": the value and its U rounded as the certificate rounds them (two significant
// digits of U); the fit's 1-sigma instead when `type_a`.
std::string ValueUncertainty(const ReportParameter& p, double factor, bool type_a) {
  const double u = type_a ? p.sigma : p.expanded;
  if (p.held || !std::isfinite(u)) return fmt::format("{:.6g} (held)", p.value * factor);
  const RoundedResult r = RoundToUncertainty(p.value * factor, u * factor);
  return fmt::format("{} +- {}", r.value, r.uncertainty);
}

// One kind of parameter over its three axes, in columns:
//   "bias (counts)        x 2051.31 +- 0.51  y 2039.57 +- 0.76  z 2062.79 +- 0.69"
std::string Triple(const ReportModel& r, const char* label, int first, const char* names[3],
                   double factor, bool type_a) {
  std::string cells[3];
  size_t width = 0;
  for (int i = 0; i < 3; ++i) {
    cells[i] = fmt::format("{} {}", names[i],
                           ValueUncertainty(r.parameters[static_cast<size_t>(first + i)], factor, type_a));
    width = std::max(width, cells[i].size() + 2);
  }
  // In columns when they fit in 80, else one blank apart.
  const size_t column = 21 + 2 * width + cells[2].size() <= 80 ? width : 0;
  std::string line = fmt::format("{:<21}", label);
  for (int i = 0; i < 3; ++i) line += i == 2 ? cells[i] : fmt::format("{:<{}}", cells[i] + " ", column);
  return line;
}

void AddParameters(const ReportModel& r, bool type_a, std::vector<std::string>* lines) {
  if (r.parameters.size() < static_cast<size_t>(kNumBaseParameters)) return;
  static const char* axes[3] = {"x", "y", "z"};
  static const char* angles[3] = {"yz", "zy", "zx"};
  lines->push_back(Triple(r, "bias (counts)", kBiasX, axes, 1.0, type_a));
  lines->push_back(Triple(r, "scale (counts/m/s^2)", kScaleX, axes, 1.0, type_a));
  lines->push_back(Triple(r, "misalignment (mrad)", kMisYZ, angles, 1e3, type_a));
}

std::string LimitFailed(const LimitCheck& c) {
  const std::string unit = c.unit.empty() ? "" : " " + c.unit;
  return fmt::format("{} {:.4g}{}, {} {:.4g}", c.what, c.value, unit, c.at_least ? "at least" : "at most",
                     c.limit);
}

std::string Ending(Verdict verdict) {
  switch (verdict) {
    case Verdict::kPass: return "Calibration complete.";
    case Verdict::kFail:
      return "Calibration recorded, and it does not conform (FAIL): what failed and the next steps are above.";
    case Verdict::kIncomplete:
      return "Calibration recorded, but INCOMPLETE: not a certificate yet; what is missing and the next steps "
             "are above.";
    case Verdict::kNoLimits: break;
  }
  return "Calibration recorded: the procedure states no limits, so it was not judged.";
}

}  // namespace

std::string EarlierEnding(Verdict verdict) {
  switch (verdict) {
    case Verdict::kPass: return "Calibration complete (in an earlier run): nothing left to do.";
    case Verdict::kFail:
      return "Calibration recorded in an earlier run; it does not conform (FAIL): what failed and the next "
             "steps are above.";
    case Verdict::kIncomplete:
      return "Calibration recorded in an earlier run, but INCOMPLETE: what is missing and the next steps are "
             "above.";
    case Verdict::kNoLimits: break;
  }
  return "Calibration recorded in an earlier run: the procedure states no limits, so it was not judged.";
}

FinalSummary BuildFinalSummary(const ReportModel& r, const std::vector<std::string>& report_paths,
                               const std::vector<std::string>& next_steps) {
  FinalSummary s;
  s.verdict = r.verdict;
  s.ending = Ending(r.verdict);
  s.lines.push_back(fmt::format("Verdict: {}", VerdictToString(r.verdict)));
  for (const LimitCheck& c : r.checks) {
    if (c.pass) continue;
    Add(&s.lines, Wrapped("  limit failed: ", LimitFailed(c)));
    if (!c.why.empty()) Add(&s.lines, Wrapped("    ", c.why));
  }
  for (const std::string& why : r.incomplete) Add(&s.lines, Wrapped("  incomplete: ", why));
  if (!next_steps.empty()) s.lines.push_back("Next:");
  for (const std::string& step : next_steps) Add(&s.lines, Wrapped("  - ", step));
  s.lines.push_back(r.budget ? "Values +- U (k = 2, about 95 %), as on the certificate:"
                             : "Values +- U = 2 x the fit's 1-sigma (no uncertainty budget):");
  AddParameters(r, false, &s.lines);
  s.lines.push_back(fmt::format("{:<21}{:.3g} m/s^2 over {} captures (noise alone: {:.3g})",
                                "residual RMS", r.residual_rms_mps2, r.captures_used, r.noise_rms_mps2));
  for (const std::string& path : report_paths) s.lines.push_back("Report: " + path);

  s.details.push_back("Values +- the fit's 1-sigma (type A alone: the captures' noise and scatter):");
  AddParameters(r, true, &s.details);
  for (const LimitCheck& c : r.checks)
    if (!c.rule.empty()) Add(&s.details, Wrapped("  ", fmt::format("{}: {}", c.what, c.rule)));
  return s;
}

}  // namespace accelcal
