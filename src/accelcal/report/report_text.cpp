#include "accelcal/report/report_text.h"

#include <cmath>

#include <fmt/core.h>

#include "accelcal/base/safe_text.h"
#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/report/certificate_text.h"
namespace accelcal {
// The sections in a scope of their own: report_html.cpp has sections of the same names, and a unity
// batch compiles the two as one file.
namespace report_text_sections {
namespace {

constexpr size_t kWidth = 80;
const char* const kAxisNames[3] = {"x", "y", "z"};

// User-typed text on paper: control characters (and DEL) become '?'.
// Text from a user or a file, safe on a terminal (base/safe_text.h).
std::string Clean(const std::string& s) { return DisplayText(s); }

std::string OrNot(const std::string& s) { return s.empty() ? kNotRecorded : Clean(s); }

// `v` with the fmt spec, or "-" when not finite.
std::string Num(double v, const char* spec = "{:.6g}") {
  return std::isfinite(v) ? fmt::format(fmt::runtime(spec), v) : "-";
}

// Words of `text` on lines of at most kWidth, the first starting with `first`, the others
// indented by `indent` spaces. A word longer than a line is cut.
std::string Wrap(const std::string& first, const std::string& text, size_t indent) {
  std::string out, line = first;
  const std::string pad(indent, ' ');
  size_t i = 0;
  bool line_has_word = false;
  while (i < text.size()) {
    while (i < text.size() && text[i] == ' ') ++i;
    size_t j = i;
    while (j < text.size() && text[j] != ' ') ++j;
    if (j == i) break;
    std::string word = text.substr(i, j - i);
    i = j;
    while (!word.empty()) {
      // (A full line leaves no room: never a negative one, which size_t would make huge.)
      const size_t used = line.size() + (line_has_word ? 1 : 0);
      const size_t room = used < kWidth ? kWidth - used : 0;
      if (word.size() <= room) {
        line += (line_has_word ? " " : "") + word;
        line_has_word = true;
        word.clear();
      } else if (!line_has_word && room > 0) {
        line += word.substr(0, room);  // a word longer than a whole line
        word = word.substr(room);
        out += line + "\n";
        line = pad;
      } else {
        out += line + "\n";
        line = pad;
        line_has_word = false;
      }
    }
  }
  return out + line + "\n";
}

std::string Field(const std::string& name, const std::string& value) {
  return Wrap(fmt::format("  {:<20}", name + ":"), Clean(value), 22);
}

std::string Heading(int number, const std::string& title) {
  const std::string t = fmt::format("{}. {}", number, title);
  return "\n" + t + "\n" + std::string(t.size(), '-') + "\n";
}

std::string LetterHeading(char letter, const std::string& title) {
  const std::string t = fmt::format("{}. {}", letter, title);
  return "\n" + t + "\n" + std::string(t.size(), '-') + "\n";
}

std::string Header(const ReportModel& m) {
  std::string out = std::string(kWidth, '=') + "\n";
  const std::string title = "ACCELEROMETER CALIBRATION REPORT";
  out += std::string((kWidth - title.size()) / 2, ' ') + title + "\n";
  out += std::string(kWidth, '=') + "\n";
  if (m.certificate.simulated)
    out += "  *** SIMULATED on the virtual bench: not a calibration of a real device ***\n";
  out += Field("Certificate No.", m.certificate.number);
  out += Field("Device (serial)", OrNot(m.meta.device));
  out += Field("Operator", OrNot(m.meta.operator_name));
  out += Field("Date (UTC)", OrNot(m.meta.date_utc));
  out += Field("Place", OrNot(m.meta.place));
  out += Field("Gravity used", m.gravity_text);
  out += Field("Procedure", OrNot(m.meta.procedure));
  out += Field("Session", m.meta.session_name.empty() ? std::string(kNotRecorded)
                                                      : m.meta.session_name + " (" + m.meta.session_path + ")");
  out += Field("Sample source", OrNot(m.meta.source));
  out += Field("Fitted from", OrNot(m.fit_source));
  out += Field("Result", std::string(VerdictToString(m.verdict)));
  for (const std::string& h : m.meta.history) out += Field("History", h);
  return out;
}

std::string CaptureTable(const ReportModel& m) {
  std::string out = fmt::format("  {} captures: {} used by the fit, {} left out.\n\n", m.captures.size(),
                                m.captures.size() - static_cast<size_t>(m.captures_left_out), m.captures_left_out);
  out += " ID Pose / mounting      Kind      r (m)  rpm Samples  Noise  Residual Status\n";
  out += "                                                     (cnt)   (m/s^2)\n";
  for (const ReportCapture& c : m.captures) {
    const CalibrationCapture& r = c.record;
    const std::string label = ShortDisplayText(r.label, 20);
    out += fmt::format("{:>3} {:<20} {:<9} {:>5} {:>4} {:>7} {:>6} {:>9} {}\n", r.id, label,
                       CaptureKindToString(r.kind), Num(r.radius_m, "{:.3f}"), Num(r.rpm, "{:.0f}"),
                       r.n_samples, Num(c.noise_counts, "{:.2f}"), Num(r.residual_mps2, "{:+.5f}"),
                       r.used ? "used" : "left out");
    if (!r.used) out += Wrap("      why: ", Clean(r.reason.empty() ? "not stated" : r.reason), 11);
  }
  return out;
}

std::string ParameterTable(const std::vector<ReportParameter>& params) {
  std::string out = "  Parameter            Value       1-sigma  Unit\n";
  for (const ReportParameter& p : params)
    out += fmt::format("  {:<12} {:>14} {:>13}  {}\n", Clean(p.name), Num(p.value, "{:.6f}"),
                       p.held ? "held" : Num(p.sigma, "{:.3g}"), Clean(std::string(UnitAfterValue(p.unit))));
  return out;
}

std::string Residuals(const ReportModel& m) {
  std::string out;
  out += fmt::format("  {:<36}{} m/s^2\n", "RMS of the residuals:", Num(m.residual_rms_mps2, "{:.6f}"));
  out += fmt::format("  {:<36}{} m/s^2\n", "Largest |residual|:", Num(m.residual_max_abs_mps2, "{:.6f}"));
  out += fmt::format("  {:<36}{} m/s^2\n",
                     m.sigma_has_own_radius ? "RMS of their noise and own radii:" : "RMS of the captures' own noise:",
                     Num(m.noise_rms_mps2, "{:.6f}"));
  out += fmt::format("  {:<36}{}\n", "chi2/dof:", Num(m.chi2_per_dof, "{:.3f}"));
  out += fmt::format("  {:<36}{}\n", "Degrees of freedom:", m.dof);
  out += fmt::format("  {:<36}{}\n", "Condition number:", Num(m.condition_number, "{:.4g}"));
  out += fmt::format("  {:<36}{}\n", "Termination:", m.termination.empty() ? "-" : m.termination);
  if (!m.optimizer.empty()) out += Wrap("  Optimizer: ", m.optimizer, 4);
  for (const std::string& w : m.warnings) out += Wrap("  Warning: ", Clean(w), 4);
  // Per-capture residuals of each model stage, as numbers (the HTML report plots them).
  out += "\n  Residual per capture (m/s^2), by model:\n";
  for (size_t s = 0; s < m.stages.size(); ++s)
    out += Wrap(fmt::format("    [{}] ", s), fmt::format("{} (RMS {})", Clean(m.stages[s].name),
                                                         Num(m.stages[s].rms_mps2, "{:.6f}")), 8);
  const size_t shown = std::min<size_t>(m.stages.size(), 5);  // 5 columns fit in 80
  std::string head = "     ID";
  for (size_t s = 0; s < shown; ++s) head += fmt::format(" {:>12}", fmt::format("[{}]", s));
  out += head + "\n";
  for (size_t i = 0; i < m.captures.size(); ++i) {
    if (!m.captures[i].record.used) continue;
    std::string row = fmt::format("    {:>3}", m.captures[i].record.id);
    for (size_t s = 0; s < shown; ++s) row += fmt::format(" {:>12}", Num(m.stages[s].residual_mps2[i], "{:+.6f}"));
    out += row + "\n";
  }
  return out;
}

std::string Diagnosis(const ReportModel& m) {
  const std::string conclusion =
      m.diagnosis_conclusion.empty() ? std::string() : Wrap("  Conclusion: ", Clean(m.diagnosis_conclusion), 4);
  if (m.effects.empty()) {
    std::string before = m.stages.empty() ? "-" : Num(m.stages.front().rms_mps2, "{:.6f}");
    return "  No effect adopted: the calibration is the nine-parameter base model.\n" +
           fmt::format("  Residual RMS {} m/s^2 ({} explain{} {} m/s^2).\n", before,
                       m.sigma_has_own_radius ? "noise and the runs' own radii" : "noise",
                       m.sigma_has_own_radius ? "" : "s", Num(m.noise_rms_mps2, "{:.6f}")) +
           conclusion;
  }
  std::string out = conclusion + fmt::format("  Before (base model): RMS {} m/s^2.  After: RMS {} m/s^2.\n",
                                Num(m.effects.front().rms_before_mps2, "{:.6f}"),
                                Num(m.effects.back().rms_after_mps2, "{:.6f}"));
  for (const ReportEffect& e : m.effects) {
    out += "\n" + Wrap("  Effect: ", Clean(e.name) + (e.corrects_readings ? " (corrects readings)" : ""), 10);
    out += fmt::format("    RMS {} -> {} m/s^2, chi2/dof {} -> {}\n", Num(e.rms_before_mps2, "{:.6f}"),
                       Num(e.rms_after_mps2, "{:.6f}"), Num(e.chi2_per_dof_before, "{:.3f}"),
                       Num(e.chi2_per_dof_after, "{:.3f}"));
    for (const ReportParameter& p : e.parameters)
      out += fmt::format("    {:<22} {:>14} +- {:<11} {}\n", Clean(p.name), Num(p.value, "{:.6g}"),
                         Num(p.sigma, "{:.3g}"), Clean(std::string(UnitAfterValue(p.unit))));
    if (!e.evidence.empty()) out += Wrap("    Evidence: ", Clean(e.evidence), 6);
  }
  return out;
}

std::string NoiseAndDrift(const ReportModel& m) {
  std::string out;
  out += fmt::format("  {:<28}{}\n", "Temperature range covered:",
                     std::isfinite(m.temp_min_c) ? fmt::format("{:.2f} .. {:.2f} degC", m.temp_min_c, m.temp_max_c)
                                                 : std::string(kNotRecorded));
  for (const std::string& path : m.pose_repeat_paths)
    out += Wrap("  Reference pose taken again: ", Clean(path) + " (counts of the mean scale; a drift or a "
                "wandering bias over the session)", 4);
  if (m.noise) {
    const std::string u = Clean(m.noise->unit);
    out += "\n" + Wrap("  Noise (", fmt::format("{}): std in {}, density in {}/sqrt(Hz)", Clean(m.noise->source), u, u), 4);
    out += "  Axis          Std  Noise density  Bias repeatability\n";
    for (int i = 0; i < 3; ++i)
      if (m.noise->axes[i])
        out += fmt::format("  {:<4} {:>12} {:>14} {:>19}\n", kAxisNames[i], Num(m.noise->axes[i]->std, "{:.4g}"),
                           Num(m.noise->axes[i]->noise_density, "{:.4g}"),
                           Num(m.noise->axes[i]->bias_repeatability, "{:.4g}"));
  } else {
    out += fmt::format("  {:<28}{}\n", "Noise analysis:", kNotRecorded);
  }
  if (m.allan) {
    const std::string u = Clean(m.allan->unit);
    out += "\n" + Wrap("  Allan deviation (", fmt::format("{}, {} Hz): N in {}/sqrt(Hz), B and drift in {}, K in {}*sqrt(Hz)",
                                                           Clean(m.allan->source), Num(m.allan->rate_hz, "{:g}"), u, u, u), 4);
    out += "  Axis  Noise density N  Bias instab. B  Random walk K    Max drift\n";
    for (int i = 0; i < 3; ++i)
      if (m.allan->axes[i]) {
        const AllanAxis& a = *m.allan->axes[i];
        out += fmt::format("  {:<4} {:>16} {:>15} {:>14} {:>12}\n", kAxisNames[i], Num(a.noise_density, "{:.4g}"),
                           Num(a.bias_instability, "{:.4g}"), Num(a.random_walk, "{:.4g}"), Num(a.max_drift, "{:.4g}"));
      }
  } else {
    out += fmt::format("  {:<28}{}\n", "Allan deviation:", kNotRecorded);
  }
  return out;
}

std::string Limits(const ReportModel& m) {
  if (m.checks.empty()) return "  The procedure states no pass/fail limits.\n";
  std::string out = "  Check                                 Measured        Limit  Result\n";
  for (const LimitCheck& c : m.checks) {
    const std::string what = c.unit.empty() ? c.what : c.what + " (" + c.unit + ")";
    // A long name on its own line, the figures on the next.
    if (what.size() > 34) out += "  " + what + "\n";
    out += fmt::format("  {:<34} {:>11} {} {:>11}  {}\n", what.size() > 34 ? "" : what, Num(c.value, "{:.4g}"),
                       c.at_least ? ">=" : "<=", Num(c.limit, "{:.4g}"), c.pass ? "PASS" : "FAIL");
    if (!c.parameter.empty()) out += Wrap("    ", fmt::format("{}: {}", c.parameter, c.rule), 6);
    if (!c.why.empty()) out += Wrap("    not met: ", Clean(c.why), 6);
  }
  out += fmt::format("\n  Overall: {}\n", VerdictToString(m.verdict));
  return out;
}

// The session's missing steps and identification, and why the verdict is INCOMPLETE.
std::string Completeness(const ReportModel& m) {
  std::string out;
  if (m.gaps) {
    if (m.gaps->steps.empty()) out += "  Every step of the procedure was done.\n";
    for (const SessionGaps::Step& s : m.gaps->steps)
      out += Wrap("  ", fmt::format("{} ({}{}): {}", Clean(s.title), s.id, s.required ? ", required" : "",
                                    Clean(s.why)), 4);
    for (const std::string& what : m.gaps->identification)
      out += Wrap("  ", fmt::format("{}: not recorded, and the procedure requires it", what), 4);
  }
  for (const std::string& why : m.incomplete) out += Wrap("  INCOMPLETE: ", why, 14);
  return out;
}

std::string Render(const ReportModel& m) {
  std::string out = Header(m);
  out += LetterHeading('A', "Results (expanded uncertainty)");
  out += CertificateResultsText(m, Wrap);
  out += LetterHeading('B', "Uncertainty budget (GUM)");
  out += UncertaintyBudgetText(m, Wrap);
  out += LetterHeading('C', "Method, equipment, traceability, conformity");
  out += CertificateStatementsText(m, Wrap);
  out += Heading(1, "Captures");
  out += CaptureTable(m);
  out += Heading(2, "Parameters (1-sigma uncertainties)");
  out += "  raw = K T^-1 a + b: bias b in counts, scale K in counts/(m/s^2),\n"
         "  misalignment angles of T in rad. The 1-sigma is the fit's own (type A); the\n"
         "  certificate's U (section A) holds every source of the budget.\n\n";
  out += ParameterTable(m.parameters);
  for (const std::string& note : m.parameter_notes) out += "\n" + Wrap("  ", note, 2);
  out += Heading(3, "Residuals");
  out += Residuals(m);
  out += Heading(4, "Diagnosis");
  out += Diagnosis(m);
  out += Heading(5, "Noise, drift and temperature");
  out += NoiseAndDrift(m);
  out += Heading(6, "Limits of the procedure");
  out += Limits(m);
  int next = 7;
  if (m.gaps || !m.incomplete.empty()) {
    out += Heading(next++, "Steps skipped or missing");
    out += Completeness(m);
  }
  if (m.bench_time) {
    out += Heading(next, "Bench time");
    const std::vector<std::string> lines = BenchTimeLines(*m.bench_time);
    for (size_t i = 0; i < lines.size(); ++i) out += i == 0 ? Wrap("  ", lines[i], 4) : "  " + lines[i] + "\n";
  }
  out += "\n" + std::string(kWidth, '-') + "\n";
  out += Wrap("  ", "Report made by " + m.tool + ".", 2);
  out += "\n  Calibrated by: ____________________     Checked by: ____________________\n";
  out += "\n  Date:          ____________________     Date:       ____________________\n";
  return out;
}

}  // namespace
}  // namespace report_text_sections

std::string RenderReportText(const ReportModel& m) { return report_text_sections::Render(m); }

}  // namespace accelcal
