#include "accelcal/app/wizard/wizard_outputs.h"

#include <filesystem>

#include "accelcal/app/report_files.h"
#include "accelcal/io/allan_file.h"

namespace accelcal {
namespace {

class OutputsBesideSession final : public WizardOutputs {
 public:
  explicit OutputsBesideSession(std::string session_path) : session_path_(std::move(session_path)) {}

  std::vector<std::string> WriteReports(const ReportInputs& inputs) override {
    return WriteSessionReports(inputs, session_path_);
  }

  std::vector<std::string> ReportPaths() const override {
    std::vector<std::string> paths;
    for (const char* extension : {"html", "txt"}) {
      std::string path = ReportPathFor(session_path_, extension);
      std::error_code ignored;  // a path that cannot be checked is not named
      if (std::filesystem::exists(path, ignored)) paths.push_back(std::move(path));
    }
    return paths;
  }

  std::string WriteAllan(const RecordAnalysis& analysis, const std::string& source,
                         double drift_window_s) override {
    const std::string path = FileBesideSession(session_path_, ".allan.json");
    WriteAllanFile(path, AllanFileText(analysis, source, drift_window_s));
    return path;
  }

 private:
  std::string session_path_;
};

}  // namespace

std::unique_ptr<WizardOutputs> MakeOutputsBesideSession(std::string session_path) {
  return std::make_unique<OutputsBesideSession>(std::move(session_path));
}

}  // namespace accelcal
