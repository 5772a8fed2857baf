// Where a session's report files go, and writing them: beside the session, named after it
// (bench1.db -> bench1.report.html, bench1.report.txt). Written beside and renamed, so a crash
// never leaves half a report.
#pragma once

#include <string>
#include <vector>

#include "accelcal/report/report_model.h"

namespace accelcal {

// `session_path` without a trailing ".db", then `suffix` (bench1.db, ".allan.json" ->
// bench1.allan.json).
std::string FileBesideSession(const std::string& session_path, const std::string& suffix);

// `session_path` without a trailing ".db", then ".report." and `extension` ("html", "txt").
std::string ReportPathFor(const std::string& session_path, const std::string& extension);

// The report of `inputs` written as HTML and text beside `session_path` (the session's name
// from the file's stem when the meta lacks it). Returns the paths written. Throws
// accelcal::Error naming the file.
std::vector<std::string> WriteSessionReports(ReportInputs inputs, const std::string& session_path);

}  // namespace accelcal
