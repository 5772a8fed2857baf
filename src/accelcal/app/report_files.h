// Where a session's report files go, and writing them: beside the session, named after it
// (bench1.db -> bench1.report.html, bench1.report.txt). Written beside and renamed, so a crash
// never leaves half a report.
#pragma once

#include <string>
#include <vector>

#include "accelcal/report/report_model.h"
#include "accelcal/session/session_journal.h"

namespace accelcal {

// `session_path` without a trailing ".db", then `suffix` (bench1.db, ".allan.json" ->
// bench1.allan.json).
std::string FileBesideSession(const std::string& session_path, const std::string& suffix);

// `session_path` without a trailing ".db", then ".report." and `extension` ("html", "txt").
std::string ReportPathFor(const std::string& session_path, const std::string& extension);

// Writes `text` to `path` (via path.tmp and a rename). Throws accelcal::Error naming the file.
void WriteReportFile(const std::string& path, const std::string& text);

// The wizard's last step: the report of `journal`'s result (with `meta` and `limits`) written
// as HTML and text beside `session_path`. Returns the paths written. Throws accelcal::Error.
std::vector<std::string> WriteSessionReports(const SessionJournal& journal, const ReportMeta& meta,
                                             const ProcedureLimits& limits,
                                             const std::string& session_path);

}  // namespace accelcal
