#include "accelcal/report/report_html.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/report/certificate_html.h"
#include "accelcal/report/svg_plot.h"

namespace accelcal {
// The sections in a scope of their own: report_text.cpp has sections of the same names, and a unity
// batch compiles the two as one file.
namespace report_html_sections {
namespace {

const char* const kAxisNames[3] = {"x", "y", "z"};
const char* const kAxisColors[3] = {"#c0392b", "#2e7d32", "#1f4e79"};
// Stage colours: the base model grey, then each adopted effect; the last stage is the result.
const char* const kStageColors[] = {"#8c8c8c", "#d35400", "#7b1fa2", "#00838f", "#1f4e79"};

std::string E(const std::string& s) { return EscapeXml(s); }
std::string OrNot(const std::string& s) {
  return s.empty() ? std::string("<span class=\"absent\">") + kNotRecorded + "</span>" : E(s);
}
std::string Num(double v, const char* spec = "{:.6g}") {
  return std::isfinite(v) ? fmt::format(fmt::runtime(spec), v) : "&ndash;";
}
// Units as written in the report (plain text) made typographic.
std::string Unit(const std::string& u) {
  std::string out = E(u);
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"m/s^2", "m/s&sup2;"},
                                 {"sqrt(Hz)", "&radic;Hz"}, {"sqrt(s)", "&radic;s"}}) {
    for (size_t at = out.find(from); at != std::string::npos; at = out.find(from, at + to.size()))
      out.replace(at, from.size(), to);
  }
  return out;
}

// A unit inside an SVG label (plain text, UTF-8): m/s^2 -> m/s².
std::string PlotUnit(std::string u) {
  for (size_t at = u.find("^2"); at != std::string::npos; at = u.find("^2", at))
    u.replace(at, 2, "\u00b2");
  return u;
}

constexpr const char* kCss = R"CSS(
:root { --ink: #1b1b1b; --muted: #5f6368; --rule: #c9ced6; --accent: #1f4e79; --pass: #1e7b34; --fail: #b3261e; }
* { box-sizing: border-box; }
body { margin: 0; background: #eef1f5; color: var(--ink);
  font: 13px/1.45 "Helvetica Neue", Helvetica, Arial, sans-serif; }
.page { max-width: 1000px; margin: 24px auto; background: #fff; padding: 36px 44px 28px;
  box-shadow: 0 1px 4px rgba(0,0,0,.15); }
header.cert { display: flex; justify-content: space-between; align-items: flex-start;
  border-bottom: 3px double var(--accent); padding-bottom: 14px; margin-bottom: 18px; }
header.cert h1 { margin: 0; font-size: 24px; letter-spacing: .04em; color: var(--accent); text-transform: uppercase; }
header.cert .sub { color: var(--muted); margin-top: 4px; }
.verdict { border: 2px solid; border-radius: 4px; padding: 8px 16px; font-weight: bold; font-size: 18px;
  letter-spacing: .08em; text-align: center; min-width: 140px; }
.verdict small { display: block; font-size: 10px; font-weight: normal; letter-spacing: 0; }
.verdict.pass { color: var(--pass); border-color: var(--pass); }
.verdict.fail { color: var(--fail); border-color: var(--fail); }
.verdict.none { color: var(--muted); border-color: var(--muted); }
h2 { font-size: 15px; color: var(--accent); border-bottom: 1px solid var(--rule); padding-bottom: 3px;
  margin: 26px 0 10px; text-transform: uppercase; letter-spacing: .05em; }
table { border-collapse: collapse; width: 100%; font-variant-numeric: tabular-nums; }
th, td { padding: 3px 8px; border-bottom: 1px solid #e4e7eb; text-align: left; vertical-align: top; }
th { background: #f3f5f8; font-weight: 600; border-bottom: 1px solid var(--rule); }
td.n, th.n { text-align: right; white-space: nowrap; }
table.ident { width: 100%; }
table.ident th { width: 22%; background: none; color: var(--muted); font-weight: normal; border-bottom: 1px solid #eef0f3; }
table.ident td { border-bottom: 1px solid #eef0f3; }
tr.out td { color: var(--muted); }
.pass { color: var(--pass); font-weight: 600; }
.fail { color: var(--fail); font-weight: 600; }
.absent { color: var(--muted); font-style: italic; }
.note { color: var(--muted); font-size: 12px; }
figure { margin: 12px 0 4px; page-break-inside: avoid; break-inside: avoid; }
figure svg { width: 100%; height: auto; display: block; }
figcaption { color: var(--muted); font-size: 12px; margin-top: 2px; }
.sign { display: grid; grid-template-columns: 1fr 1fr; gap: 36px; margin-top: 36px; }
.sign div { border-top: 1px solid var(--ink); padding-top: 4px; color: var(--muted); font-size: 12px; }
footer { margin-top: 24px; color: var(--muted); font-size: 11px; border-top: 1px solid var(--rule); padding-top: 6px; }
@media print {
  @page { size: A4; margin: 14mm 12mm; }
  body { background: #fff; font-size: 10.5pt; }
  .page { box-shadow: none; margin: 0; max-width: none; padding: 0; }
  section, table, figure { page-break-inside: avoid; break-inside: avoid; }
  h2 { page-break-after: avoid; break-after: avoid; }
  th { background: #f3f5f8 !important; -webkit-print-color-adjust: exact; print-color-adjust: exact; }
}
)CSS";

std::string Row(const std::string& name, const std::string& value_html) {
  return fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", name, value_html);
}

std::string Header(const ReportModel& m) {
  const char* cls = m.verdict == Verdict::kPass ? "pass"
                    : m.verdict == Verdict::kFail || m.verdict == Verdict::kIncomplete ? "fail"
                                                                                      : "none";
  std::string out = "<header class=\"cert\"><div><h1>Accelerometer calibration report</h1>"
                    "<div class=\"sub\">Three-axis MEMS accelerometer &middot; nine-parameter model "
                    "(bias, scale, misalignment) with their expanded uncertainty</div></div>\n";
  out += fmt::format("<div class=\"verdict {}\">{}<small>against the procedure&rsquo;s limits</small></div></header>\n",
                     cls, E(std::string(VerdictToString(m.verdict))));
  out += "<table class=\"ident\">\n";
  out += Row("Certificate No.", "<span class=\"certno\">" + E(m.certificate.number) + "</span>");
  out += Row("Device (serial)", OrNot(m.meta.device));
  out += Row("Operator", OrNot(m.meta.operator_name));
  out += Row("Date (UTC)", OrNot(m.meta.date_utc));
  out += Row("Place", OrNot(m.meta.place));
  out += Row("Gravity used", Unit(m.gravity_text));
  out += Row("Procedure", OrNot(m.meta.procedure));
  out += Row("Session", m.meta.session_name.empty() ? OrNot("")
                                                     : E(m.meta.session_name) + " <span class=\"note\">(" +
                                                           E(m.meta.session_path) + ")</span>");
  out += Row("Sample source", OrNot(m.meta.source));
  out += Row("Temperature range", std::isfinite(m.temp_min_c)
                                      ? fmt::format("{:.2f} &ndash; {:.2f} &deg;C", m.temp_min_c, m.temp_max_c)
                                      : OrNot(""));
  for (const std::string& h : m.meta.history) out += Row("History", E(h));
  out += "</table>\n";
  return out;
}

// The session's missing steps and identification, and why the verdict is INCOMPLETE.
std::string Completeness(const ReportModel& m) {
  if (!m.gaps && m.incomplete.empty()) return "";
  std::string out;
  for (const std::string& why : m.incomplete)
    out += fmt::format("<p class=\"fail\"><b>INCOMPLETE:</b> {}</p>\n", E(why));
  if (m.gaps && m.gaps->steps.empty()) out += "<p class=\"note\">Every step of the procedure was done.</p>\n";
  if (m.gaps && !m.gaps->steps.empty()) {
    out += "<table><tr><th>Step skipped or missing</th><th>Required</th><th>Why</th></tr>\n";
    for (const SessionGaps::Step& s : m.gaps->steps)
      out += fmt::format("<tr><td>{} <span class=\"note\">({})</span></td><td>{}</td><td>{}</td></tr>\n",
                         E(s.title), E(s.id), s.required ? "yes" : "no", E(s.why));
    out += "</table>\n";
  }
  return out;
}

std::string Limits(const ReportModel& m) {
  std::string out = "<section><h2>1. Result against the procedure&rsquo;s limits</h2>\n";
  out += Completeness(m);
  if (m.checks.empty()) return out + "<p class=\"absent\">The procedure states no pass/fail limits.</p></section>\n";
  out += "<table><tr><th>Check</th><th class=\"n\">Measured</th><th class=\"n\">Limit</th><th>Result</th></tr>\n";
  for (const LimitCheck& c : m.checks) {
    // The parameter judged, how, and (not met) why and what would bring it within.
    std::string note = c.parameter.empty() ? "" : " <span class=\"note\">(" + E(c.parameter) + ")</span>";
    if (!c.rule.empty()) note += "<br><span class=\"note\">" + E(c.rule) + "</span>";
    if (!c.why.empty()) note += "<br><span class=\"fail\">" + E(c.why) + "</span>";
    out += fmt::format("<tr><td>{}{}{}</td><td class=\"n\">{}</td><td class=\"n\">{} {}</td><td class=\"{}\">{}</td></tr>\n",
                       E(c.what), c.unit.empty() ? "" : " (" + Unit(c.unit) + ")", note, Num(c.value, "{:.4g}"),
                       c.at_least ? "&ge;" : "&le;", Num(c.limit, "{:.4g}"), c.pass ? "pass" : "fail",
                       c.pass ? "PASS" : "FAIL");
  }
  return out + "</table></section>\n";
}

std::string Parameters(const ReportModel& m) {
  std::string out = "<section><h2>2. Calibration parameters</h2>\n"
                    "<p class=\"note\">Model raw = K T<sup>&minus;1</sup> a + b: bias b in counts, scale K in "
                    "counts per m/s&sup2;, misalignment angles of T in rad. Uncertainties are the fit&rsquo;s "
                    "1&sigma; (type A); the certificate&rsquo;s U above holds every source.</p>\n"
                    "<table><tr><th>Parameter</th><th class=\"n\">Value</th><th class=\"n\">1&sigma;</th>"
                    "<th>Unit</th></tr>\n";
  for (const ReportParameter& p : m.parameters)
    out += fmt::format("<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td>{}</td></tr>\n", E(p.name),
                       Num(p.value, "{:.6f}"), p.held ? "held" : Num(p.sigma, "{:.3g}"), Unit(std::string(UnitAfterValue(p.unit))));
  out += "</table>\n";
  for (const std::string& note : m.parameter_notes) out += "<p class=\"note\">" + E(note) + "</p>\n";
  return out + "</section>\n";
}

std::string ResidualPlot(const ReportModel& m) {
  SvgPlotOptions o;
  o.title = "Residual per capture, before and after each adopted effect";
  o.x_label = "capture id";
  o.y_label = PlotUnit("residual |a| - |f| (m/s^2)");
  o.zero_line = true;
  o.integer_x_ticks = true;
  SvgPlot plot(o);
  const size_t n = m.stages.size();
  for (size_t s = 0; s < n; ++s) {
    SvgSeries series;
    series.name = m.stages[s].name + (s + 1 == n && n > 1 ? " (adopted)" : "");
    series.color = (s + 1 == n) ? "#1f4e79" : kStageColors[std::min<size_t>(s, 3)];
    series.line = false;
    series.markers = true;
    series.marker = s + 1 == n ? SvgSeries::Marker::kDiamond : s == 0 ? SvgSeries::Marker::kCircle : SvgSeries::Marker::kSquare;
    for (size_t i = 0; i < m.captures.size(); ++i) {
      series.x.push_back(m.captures[i].record.id);
      series.y.push_back(m.stages[s].residual_mps2[i]);
    }
    plot.Add(series);
  }
  return "<figure>" + plot.Render() +
         "<figcaption>Residual of every capture the fit used under the base model and after each adopted "
         "effect; the RMS of each is in the table below.</figcaption></figure>\n";
}

std::string MagnitudePlot(const ReportModel& m) {
  SvgPlotOptions o;
  o.title = "Measured magnitude against the reference";
  o.x_label = PlotUnit("reference |f| (m/s^2)");
  o.y_label = PlotUnit("calibrated |a| (m/s^2)");
  SvgPlot plot(o);
  SvgSeries ideal, stat, turn;
  ideal.name = "|a| = |f|";
  ideal.color = "#8c8c8c";
  ideal.dashed = true;
  stat.name = "static poses";
  turn.name = "turntable runs";
  turn.color = "#d35400";
  turn.marker = SvgSeries::Marker::kSquare;
  double lo = INFINITY, hi = -INFINITY;
  for (const ReportCapture& c : m.captures) {
    if (!c.record.used || !std::isfinite(c.magnitude_mps2())) continue;
    SvgSeries& s = c.record.kind == CaptureKind::kStatic ? stat : turn;
    s.x.push_back(c.record.reference_mps2);
    s.y.push_back(c.magnitude_mps2());
    lo = std::min(lo, c.record.reference_mps2);
    hi = std::max(hi, c.record.reference_mps2);
  }
  for (SvgSeries* s : {&stat, &turn}) {
    s->line = false;
    s->markers = true;
  }
  if (lo <= hi) {
    ideal.x = {lo, hi};
    ideal.y = {lo, hi};
  }
  // Nine poses at g, three runs per radius: without this they draw as four dots.
  const double width = std::max(hi - lo, 1.0) * 0.025;
  for (SvgSeries* s : {&stat, &turn}) SpreadCoincident(&s->x, width);
  plot.Add(ideal);
  if (!stat.x.empty()) plot.Add(stat);
  if (!turn.x.empty()) plot.Add(turn);
  return "<figure>" + plot.Render() +
         "<figcaption>Each used capture&rsquo;s calibrated magnitude against the specific force it should "
         "show (g at rest; &radic;(g&sup2; + (&omega;&sup2;r)&sup2;) on the turntable). Captures with the same "
         "reference are spread sideways (by about 2.5 % of the axis each) so every one shows.</figcaption></figure>\n";
}

std::string Residuals(const ReportModel& m) {
  std::string out = "<section><h2>3. Residuals</h2>\n<table>\n";
  out += fmt::format("<tr><td>RMS of the residuals</td><td class=\"n\">{} m/s&sup2;</td>"
                     "<td>Largest |residual|</td><td class=\"n\">{} m/s&sup2;</td></tr>\n",
                     Num(m.residual_rms_mps2, "{:.6f}"), Num(m.residual_max_abs_mps2, "{:.6f}"));
  out += fmt::format("<tr><td>RMS of the captures&rsquo; {}</td><td class=\"n\">{} m/s&sup2;</td>"
                     "<td>&chi;&sup2;/dof (dof)</td><td class=\"n\">{} ({})</td></tr>\n",
                     m.sigma_has_own_radius ? "noise and own radii" : "own noise", Num(m.noise_rms_mps2, "{:.6f}"), Num(m.chi2_per_dof, "{:.3f}"), m.dof);
  out += fmt::format("<tr><td>Captures used / left out</td><td class=\"n\">{} / {}</td>"
                     "<td>Condition number</td><td class=\"n\">{}</td></tr>\n",
                     m.captures_used, m.captures_left_out, Num(m.condition_number, "{:.4g}"));
  out += fmt::format("<tr><td>Termination</td><td colspan=\"3\">{}{}</td></tr>\n", OrNot(m.termination),
                     m.optimizer.empty() ? "" : " <span class=\"note\">&middot; " + E(m.optimizer) + "</span>");
  out += "</table>\n";
  for (const std::string& w : m.warnings) out += "<p class=\"fail\">Warning: " + E(w) + "</p>\n";
  out += ResidualPlot(m);
  out += "<table><tr><th>Model</th><th class=\"n\">Residual RMS</th></tr>\n";
  for (const ResidualStage& s : m.stages)
    out += fmt::format("<tr><td>{}</td><td class=\"n\">{} m/s&sup2;</td></tr>\n", E(s.name), Num(s.rms_mps2, "{:.6f}"));
  out += "</table>\n";
  out += MagnitudePlot(m);
  return out + "</section>\n";
}

std::string Diagnosis(const ReportModel& m) {
  std::string out = "<section><h2>4. Diagnosis</h2>\n";
  if (!m.diagnosis_conclusion.empty()) out += "<p>" + E(m.diagnosis_conclusion) + "</p>\n";
  if (m.effects.empty())
    return out + fmt::format("<p>No effect adopted: the calibration is the nine-parameter base model "
                             "(residual RMS {} m/s&sup2;; the captures&rsquo; {} {} m/s&sup2;).</p></section>\n",
                             Num(m.residual_rms_mps2, "{:.6f}"),
                             m.sigma_has_own_radius ? "noise and own radii explain" : "noise explains",
                             Num(m.noise_rms_mps2, "{:.6f}"));
  out += "<table><tr><th>Adopted effect</th><th class=\"n\">RMS before</th><th class=\"n\">RMS after</th>"
         "<th class=\"n\">&chi;&sup2;/dof before</th><th class=\"n\">after</th><th>Corrects readings</th></tr>\n";
  for (const ReportEffect& e : m.effects)
    out += fmt::format("<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td>"
                       "<td class=\"n\">{}</td><td>{}</td></tr>\n",
                       E(e.name), Num(e.rms_before_mps2, "{:.6f}"), Num(e.rms_after_mps2, "{:.6f}"),
                       Num(e.chi2_per_dof_before, "{:.3f}"), Num(e.chi2_per_dof_after, "{:.3f}"),
                       e.corrects_readings ? "yes" : "no");
  out += "</table>\n";
  for (const ReportEffect& e : m.effects) {
    out += "<p><b>" + E(e.name) + "</b>";
    for (const ReportParameter& p : e.parameters)
      out += fmt::format(" &middot; {} = {} &plusmn; {} {}", E(p.name), Num(p.value), Num(p.sigma, "{:.3g}"), Unit(std::string(UnitAfterValue(p.unit))));
    if (!e.evidence.empty()) out += "<br><span class=\"note\">" + E(e.evidence) + "</span>";
    out += "</p>\n";
  }
  return out + "</section>\n";
}

std::string Captures(const ReportModel& m) {
  std::string out = "<section><h2>5. Captures</h2>\n<table><tr><th class=\"n\">ID</th><th>Pose / mounting</th>"
                    "<th>Kind</th><th class=\"n\">r (m)</th><th class=\"n\">rpm</th><th class=\"n\">Samples</th>"
                    "<th class=\"n\">Noise (counts)</th><th class=\"n\">Residual (m/s&sup2;)</th><th>Status</th></tr>\n";
  for (const ReportCapture& c : m.captures) {
    const CalibrationCapture& r = c.record;
    out += fmt::format("<tr{}><td class=\"n\">{}</td><td>{}</td><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td>"
                       "<td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td>{}</td></tr>\n",
                       r.used ? "" : " class=\"out\"", r.id, E(r.label), CaptureKindToString(r.kind),
                       Num(r.radius_m, "{:.3f}"), Num(r.rpm, "{:.0f}"), r.n_samples, Num(c.noise_counts, "{:.2f}"),
                       Num(r.residual_mps2, "{:+.5f}"),
                       r.used ? std::string("used") : "left out: " + E(r.reason.empty() ? "not stated" : r.reason));
  }
  return out + "</table></section>\n";
}

// Read-off labels of the three axes sit close together: stack them by value, the lowest
// point's label nearest to it, so they never overlap.
void AddStackedMarks(std::vector<SvgMark> marks, SvgPlot* plot) {
  std::sort(marks.begin(), marks.end(), [](const SvgMark& a, const SvgMark& b) { return a.y < b.y; });
  for (size_t k = 0; k < marks.size(); ++k) {
    marks[k].label_dy_px = -8.0 - 15.0 * static_cast<double>(k);
    plot->Mark(marks[k]);
  }
}

std::string AllanPlot(const AllanSection& a) {
  SvgPlotOptions o;
  o.title = "Allan deviation";
  o.x_label = "averaging time \u03c4 (s)";
  o.y_label = PlotUnit("Allan deviation (" + a.unit + ")");
  o.log_x = o.log_y = true;
  o.height_px = 360;
  SvgPlot plot(o);
  std::vector<SvgMark> n_marks, b_marks;
  for (int i = 0; i < 3; ++i) {
    if (!a.axes[i] || a.axes[i]->tau_s.empty()) continue;
    const AllanAxis& ax = *a.axes[i];
    SvgSeries s;
    s.name = std::string("axis ") + kAxisNames[i];
    s.color = kAxisColors[i];
    s.x = ax.tau_s;
    s.y = ax.adev;
    if (!ax.adev_hi.empty() && !ax.adev_lo.empty()) {
      s.band_lo = ax.adev_lo;
      s.band_hi = ax.adev_hi;
    }
    plot.Add(s);
    // Read-offs: white-noise density at tau = 1 s, and the flat minimum (bias instability).
    if (std::isfinite(ax.noise_density) && ax.tau_s.front() <= 1.0 && ax.tau_s.back() >= 1.0)
      n_marks.push_back({1.0, ax.noise_density, fmt::format("{}: N {:.3g}", kAxisNames[i], ax.noise_density), kAxisColors[i]});
    size_t k = 0;  // the curve's minimum, skipping points the analysis could not give (NaN)
    for (size_t i2 = 0; i2 < ax.adev.size(); ++i2)
      if (std::isfinite(ax.adev[i2]) && !(ax.adev[k] <= ax.adev[i2])) k = i2;
    if (!std::isfinite(ax.adev[k])) continue;
    b_marks.push_back({ax.tau_s[k], ax.adev[k],
                       std::isfinite(ax.bias_instability) ? fmt::format("{}: B {:.3g}", kAxisNames[i], ax.bias_instability)
                                                          : fmt::format("{}: min", kAxisNames[i]),
                       kAxisColors[i]});
  }
  AddStackedMarks(n_marks, &plot);
  AddStackedMarks(b_marks, &plot);
  return "<figure>" + plot.Render() +
         "<figcaption>Overlapping Allan deviation per axis; the shaded band is its confidence interval. "
         "Circles mark the read-offs: N at &tau; = 1 s (white noise) and B at the curve&rsquo;s minimum "
         "(bias instability).</figcaption></figure>\n";
}

std::string NoiseAndDrift(const ReportModel& m) {
  std::string out = "<section><h2>6. Noise, drift and temperature</h2>\n";
  out += fmt::format("<p>Temperature range covered: {}</p>\n",
                     std::isfinite(m.temp_min_c) ? fmt::format("{:.2f} &ndash; {:.2f} &deg;C", m.temp_min_c, m.temp_max_c)
                                                 : OrNot(""));
  for (const std::string& path : m.pose_repeat_paths)
    out += "<p>Reference pose taken again: " + E(path) +
           " (counts of the mean scale; a drift or a wandering bias over the session)</p>\n";
  if (m.noise) {
    const std::string u = Unit(m.noise->unit);
    out += fmt::format("<p class=\"note\">Noise analysis ({}).</p>\n<table><tr><th>Axis</th><th class=\"n\">Std ({})</th>"
                       "<th class=\"n\">Noise density ({}/&radic;Hz)</th><th class=\"n\">Bias repeatability ({})</th></tr>\n",
                       E(m.noise->source), u, u, u);
    for (int i = 0; i < 3; ++i)
      if (m.noise->axes[i])
        out += fmt::format("<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>\n",
                           kAxisNames[i], Num(m.noise->axes[i]->std, "{:.4g}"),
                           Num(m.noise->axes[i]->noise_density, "{:.4g}"),
                           Num(m.noise->axes[i]->bias_repeatability, "{:.4g}"));
    out += "</table>\n";
  } else {
    out += "<p>Noise analysis: " + OrNot("") + "</p>\n";
  }
  if (m.allan) {
    const std::string u = Unit(m.allan->unit);
    out += fmt::format("<p class=\"note\">Allan deviation ({}, {} Hz).</p>\n<table><tr><th>Axis</th>"
                       "<th class=\"n\">Noise density N ({}/&radic;Hz)</th><th class=\"n\">Bias instability B ({})</th>"
                       "<th class=\"n\">Random walk K ({}&middot;&radic;Hz)</th><th class=\"n\">Max drift ({})</th></tr>\n",
                       E(m.allan->source), Num(m.allan->rate_hz, "{:g}"), u, u, u, u);
    for (int i = 0; i < 3; ++i)
      if (m.allan->axes[i]) {
        const AllanAxis& a = *m.allan->axes[i];
        out += fmt::format("<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td>"
                           "<td class=\"n\">{}</td></tr>\n",
                           kAxisNames[i], Num(a.noise_density, "{:.4g}"), Num(a.bias_instability, "{:.4g}"),
                           Num(a.random_walk, "{:.4g}"), Num(a.max_drift, "{:.4g}"));
      }
    out += "</table>\n" + AllanPlot(*m.allan);
  } else {
    out += "<p>Allan deviation: " + OrNot("") + "</p>\n";
  }
  return out + "</section>\n";
}

std::string Render(const ReportModel& m) {
  std::string title = "Calibration report";
  if (!m.meta.device.empty()) title += " " + m.meta.device;
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out += "<title>" + E(title) + "</title>\n<style>" + std::string(kCss) + CertificateCss(m) + "</style>\n</head>\n<body>\n<div class=\"page\">\n";
  out += SimulatedMarkHtml(m);
  out += Header(m);
  out += CertificateResultsHtml(m);
  out += Limits(m);
  out += Parameters(m);
  out += Residuals(m);
  out += Diagnosis(m);
  out += Captures(m);
  out += NoiseAndDrift(m);
  out += UncertaintyBudgetHtml(m);
  out += CertificateStatementsHtml(m);
  out += "<div class=\"sign\"><div>Calibrated by (name, signature, date)</div>"
         "<div>Checked by (name, signature, date)</div></div>\n";
  out += "<footer>Report made by " + E(m.tool) + " from " + OrNot(m.fit_source) +
         ". Uncertainties are 1&sigma; from the fit&rsquo;s covariance, scaled by &radic;max(1, &chi;&sup2;/dof).</footer>\n";
  return out + "</div>\n</body>\n</html>\n";
}

}  // namespace
}  // namespace report_html_sections

std::string RenderReportHtml(const ReportModel& m) { return report_html_sections::Render(m); }

}  // namespace accelcal
