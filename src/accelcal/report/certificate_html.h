// The certificate's parts of the HTML report (report_html.h): its number and SIMULATED mark,
// the page footer of the print ("page x of y" with the number, CSS paged media), the results
// with their expanded uncertainty in every unit, the uncertainty budget, and the method,
// equipment, ambient conditions, traceability, decision rule and conformity.
#pragma once

#include <string>

#include "accelcal/report/report_model.h"

namespace accelcal {

// CSS for the parts below, and the print's page margin boxes (number, page x of y).
std::string CertificateCss(const ReportModel& m);
// The diagonal SIMULATED mark (on every printed page); empty for a real bench.
std::string SimulatedMarkHtml(const ReportModel& m);
std::string CertificateResultsHtml(const ReportModel& m);
std::string UncertaintyBudgetHtml(const ReportModel& m);
std::string CertificateStatementsHtml(const ReportModel& m);

}  // namespace accelcal
