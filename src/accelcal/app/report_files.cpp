#include "accelcal/app/report_files.h"

#include <fmt/core.h>

#include "accelcal/io/atomic_write.h"
#include "accelcal/base/error.h"
#include "accelcal/report/report_html.h"
#include "accelcal/report/report_text.h"

namespace accelcal {

std::string FileBesideSession(const std::string& session_path, const std::string& suffix) {
  std::string stem = session_path;
  if (stem.size() > 3 && stem.compare(stem.size() - 3, 3, ".db") == 0) stem.resize(stem.size() - 3);
  return stem + suffix;
}

std::string ReportPathFor(const std::string& session_path, const std::string& extension) {
  return FileBesideSession(session_path, ".report." + extension);
}

std::vector<std::string> WriteSessionReports(ReportInputs in, const std::string& session_path) {
  if (in.meta.session_name.empty()) {
    // The file's stem, as `accelcal sessions` names it.
    std::string name = session_path.substr(session_path.find_last_of('/') + 1);
    if (name.size() > 3 && name.compare(name.size() - 3, 3, ".db") == 0) name.resize(name.size() - 3);
    in.meta.session_name = name;
  }
  const ReportModel model = BuildReportModel(in);
  const std::vector<std::string> paths = {ReportPathFor(session_path, "html"), ReportPathFor(session_path, "txt")};
  WriteFileAtomically(paths[0], RenderReportHtml(model));
  WriteFileAtomically(paths[1], RenderReportText(model));
  return paths;
}

}  // namespace accelcal
