// The certificate's sections of the text report (report_text.h), 80 columns: the results with
// their expanded uncertainty in every unit, the uncertainty budget per parameter, the method,
// equipment, ambient conditions, traceability, decision rule and conformity.
#pragma once

#include <string>

#include "accelcal/report/report_model.h"

namespace accelcal {

// `wrap(first, text, indent)`: the report's word wrapper (report_text.cpp), so both share it.
using TextWrapper = std::string (*)(const std::string&, const std::string&, size_t);

std::string CertificateResultsText(const ReportModel& m, TextWrapper wrap);
std::string UncertaintyBudgetText(const ReportModel& m, TextWrapper wrap);
std::string CertificateStatementsText(const ReportModel& m, TextWrapper wrap);

// The number of significant digits a budget column shows: "1.23e-05", "0.0123"; "-" when not
// finite; "inf" for infinite degrees of freedom.
std::string BudgetNumber(double v);
std::string DofText(double dof);

}  // namespace accelcal
