#include "accelcal/report/certificate_html.h"

#include <cmath>

#include <fmt/core.h>

#include "accelcal/report/certificate_text.h"
#include "accelcal/report/svg_plot.h"

namespace accelcal {
namespace {

std::string E(const std::string& s) { return EscapeXml(s); }

std::string Typo(const std::string& text) {
  std::string out = E(text);
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"m/s^2", "m/s&sup2;"},
                                 {"+-", "&plusmn;"}, {"nu_eff", "&nu;<sub>eff</sub>"}}) {
    for (size_t at = out.find(from); at != std::string::npos; at = out.find(from, at + to.size()))
      out.replace(at, from.size(), to);
  }
  return out;
}

// Text safe inside a CSS string: the certificate number is [A-Za-z0-9._-] already; anything
// else is dropped all the same.
std::string CssString(const std::string& s) {
  std::string out;
  for (char c : s)
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' || c == ' ') out += c;
  return out;
}

}  // namespace

std::string CertificateCss(const ReportModel& m) {
  std::string css = R"CSS(
.certno { font-family: "DejaVu Sans Mono", monospace; font-weight: 600; }
.simulated-mark { position: fixed; top: 42%; left: 0; right: 0; text-align: center; z-index: 10;
  font-size: 96px; font-weight: bold; letter-spacing: .12em; color: rgba(179, 38, 30, .13);
  transform: rotate(-30deg); pointer-events: none; }
.simulated-banner { border: 2px solid var(--fail); color: var(--fail); font-weight: bold; text-align: center;
  padding: 4px; margin-bottom: 12px; letter-spacing: .06em; }
table.results td.forms span { display: inline-block; margin-right: 18px; white-space: nowrap; }
table.budget td, table.budget th { font-size: 12px; padding: 2px 6px; }
table.budget tbody th { background: #f8f9fb; text-align: left; }
table.budget tbody th span { font-weight: normal; color: var(--muted); margin-left: 10px; }
ul.trace { margin: 4px 0 8px 18px; padding: 0; }
@media print {
  table.budget { break-inside: auto; page-break-inside: auto; }
  table.budget tbody { break-inside: avoid; page-break-inside: avoid; }
  table.budget thead { display: table-header-group; }
  .simulated-mark { font-size: 80pt; }
)CSS";
  css += fmt::format(
      "  @page {{ @bottom-left {{ content: \"Certificate No. {}\"; font-size: 8pt; color: #5f6368; }}\n"
      "    @bottom-right {{ content: \"Page \" counter(page) \" of \" counter(pages); font-size: 8pt; color: #5f6368; }} }}\n}}\n",
      CssString(m.certificate.number));
  return css;
}

std::string SimulatedMarkHtml(const ReportModel& m) {
  if (!m.certificate.simulated) return "";
  return "<div class=\"simulated-mark\" aria-hidden=\"true\">SIMULATED</div>\n"
         "<div class=\"simulated-banner\">SIMULATED &mdash; made on the virtual bench, not a calibration "
         "of a real device</div>\n";
}

std::string CertificateResultsHtml(const ReportModel& m) {
  const Certificate& c = m.certificate;
  std::string out = "<section><h2>Results with expanded uncertainty</h2>\n"
                    "<table class=\"results\"><tr><th>Quantity</th><th>Value &plusmn; U, in each unit</th>"
                    "<th class=\"n\">k</th><th class=\"n\">&nu;<sub>eff</sub></th></tr>\n";
  for (const CertificateResult& r : c.results) {
    std::string forms;
    for (const std::string& f : r.forms) forms += "<span>" + Typo(f) + "</span>";
    out += fmt::format("<tr><td>{}</td><td class=\"forms\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>\n",
                       E(r.quantity), forms, r.held ? "&ndash;" : BudgetNumber(r.coverage_factor),
                       r.held ? "&ndash;" : DofText(r.effective_dof));
  }
  out += "</table>\n<p class=\"note\">" + Typo(c.coverage) + "</p>\n";
  out += "<p class=\"note\">" + Typo(c.limited_by) + "</p>\n";
  if (!c.not_stated.empty()) {
    std::string names;
    for (const std::string& n : c.not_stated) names += (names.empty() ? "" : ", ") + E(n);
    out += "<p class=\"fail\">Not stated, so not in U: " + names +
           " (the procedure&rsquo;s [equipment] gives no uncertainty for it).</p>\n";
  }
  return out + "</section>\n";
}

std::string UncertaintyBudgetHtml(const ReportModel& m) {
  std::string out = "<section class=\"budget\"><h2>Uncertainty budget (GUM)</h2>\n";
  if (!m.budget) return out + "<p class=\"absent\">No uncertainty budget was made for this calibration.</p></section>\n";
  out += "<p class=\"note\">For each parameter: each source&rsquo;s standard uncertainty u(x), its sensitivity "
         "coefficient c (the fit&rsquo;s response, in the parameter&rsquo;s unit per unit of x) and its part "
         "|c|&nbsp;u(x) of the combined standard uncertainty u<sub>c</sub>, in the parameter&rsquo;s unit.</p>\n";
  out += "<table class=\"budget\"><thead><tr><th>Source</th><th>Type</th><th class=\"n\">u(x)</th><th>Unit of x</th>"
         "<th class=\"n\">c</th><th class=\"n\">|c| u(x)</th><th class=\"n\">dof</th></tr></thead>\n";
  for (const ParameterBudget& p : m.budget->parameters) {
    out += fmt::format("<tbody><tr><th colspan=\"7\">{} ({})<span>u<sub>c</sub> = {} &middot; &nu;<sub>eff</sub> = {} "
                       "&middot; k = {} &middot; U = {}</span></th></tr>\n",
                       E(p.name), Typo(p.unit), BudgetNumber(p.combined), DofText(p.effective_dof),
                       BudgetNumber(p.coverage_factor), BudgetNumber(p.expanded));
    for (const BudgetContribution& b : p.contributions)
      out += fmt::format("<tr><td>{}</td><td>{}</td><td class=\"n\">{}</td><td>{}</td><td class=\"n\">{}</td>"
                         "<td class=\"n\">{}</td><td class=\"n\">{}</td></tr>\n",
                         E(b.quantity), std::string(1, b.type), BudgetNumber(b.standard_uncertainty),
                         Typo(b.type == 'A' ? p.unit : b.quantity_unit),
                         b.type == 'A' ? std::string("1") : BudgetNumber(b.sensitivity), BudgetNumber(b.contribution),
                         DofText(b.dof));
    out += "</tbody>\n";
  }
  out += "</table>\n";
  if (!m.budget->parameters.empty()) {
    out += "<ul class=\"trace note\">";
    for (const BudgetContribution& b : m.budget->parameters.front().contributions)
      if (!b.note.empty()) out += "<li>" + E(b.quantity) + ": " + E(b.note) + "</li>";
    out += "</ul>\n";
  }
  return out + "</section>\n";
}

std::string CertificateStatementsHtml(const ReportModel& m) {
  const Certificate& c = m.certificate;
  std::string out = "<section><h2>Method, equipment and conditions</h2>\n<p>" + Typo(c.method) + "</p>\n";
  out += "<table><tr><th>Equipment</th><th>Item</th><th>Identification</th><th class=\"n\">Standard uncertainty</th></tr>\n";
  if (c.equipment.empty())
    out += "<tr><td colspan=\"4\" class=\"absent\">The procedure lists no equipment.</td></tr>\n";
  for (const EquipmentItem& e : c.equipment)
    out += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td class=\"n\">{}</td></tr>\n",
                       E(std::string(InfoOf(e.role).key)), E(e.name),
                       e.identification.empty() ? "<span class=\"absent\">not recorded</span>" : E(e.identification),
                       E(DescribeUncertainty(e)));
  out += "</table>\n<p>Ambient conditions: " + E(c.ambient) + "</p>\n</section>\n";
  out += "<section><h2>Traceability and conformity</h2>\n<ul class=\"trace\">";
  for (const std::string& t : c.traceability) out += "<li>" + Typo(t) + "</li>";
  out += "</ul>\n<p><b>Decision rule.</b> " + E(c.decision_rule) + "</p>\n";
  out += "<p><b>Statement of conformity.</b> " + E(c.conformity) + "</p>\n</section>\n";
  return out;
}

}  // namespace accelcal
