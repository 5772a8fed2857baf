// The calibration certificate's content (ISO/IEC 17025 clause 7.8; GUM, JCGM 100:2008): what
// the report adds to make it a certificate a lab can sign. Gathered once from the report's
// inputs and model, so the text and HTML renderings state the same things:
//  - its number: the lab's once the session is published to a lab's store (unique lab-wide,
//    ReportMeta::certificate_number, docs/lab.md); before, unique per session and stable across
//    re-renders (derived from the session's name and its recorded calibration, never from the
//    time of rendering);
//  - the method, the equipment with identifications, the ambient conditions recorded;
//  - the results with their expanded uncertainty (the budget's), rounded to it (two
//    significant digits of U), each in its forms: offset in counts, m/s^2 and mg, scale in
//    counts/(m/s^2) and counts/g, misalignment in rad, mrad and deg;
//  - the traceability statement (each reference and what it is traced to, as the procedure
//    states it), the decision rule and the statement of conformity with the procedure's limits;
//  - SIMULATED when the samples came from the virtual bench.
#pragma once

#include <string>
#include <vector>

#include "accelcal/session/equipment.h"

namespace accelcal {

struct ReportInputs;
struct ReportModel;

// One result as the certificate states it.
struct CertificateResult {
  std::string name;                 // "bias_x", ...
  std::string quantity;             // "offset x", "scale x", "misalignment a_yz"
  // The value with its U in each form, first the calibration's own unit:
  // "2051.334 +- 0.044 counts", "+0.087 +- 0.0013 m/s^2", ...
  std::vector<std::string> forms;
  double coverage_factor = kNaN;
  double effective_dof = kNaN;      // infinity: every input known
  bool held = false;                // held, not fitted: no uncertainty
};

struct Certificate {
  std::string number;               // the lab's ("LAB-000042"), else "ACC-<session>-<8 hex>"
  bool simulated = false;           // the samples came from the virtual bench
  std::string method;               // in words
  std::vector<EquipmentItem> equipment;
  std::string ambient;              // temperature range recorded; what was not
  std::vector<CertificateResult> results;
  bool has_budget = false;          // results carry U; else the 1-sigma of the fit alone
  std::string coverage;             // how U was obtained, one paragraph
  std::string limited_by;           // which uncertainty dominates, one paragraph (limited_by_text.h)
  std::vector<std::string> not_stated;  // reference quantities without a stated uncertainty
  std::vector<std::string> traceability;  // one line per reference
  std::string decision_rule;
  std::string conformity;
};

// The certificate of the report `m` built from `in` (call at the end of BuildReportModel).
Certificate MakeCertificate(const ReportInputs& in, const ReportModel& m);

// The number: "ACC-" + the session name (or "FILE" for a calibration file alone) + "-" + eight
// hex digits of a hash (FNV-1a) of the session name and the calibration's nine parameters at
// full precision.
std::string CertificateNumber(const std::string& session_name, const SensorModel& model);

}  // namespace accelcal
