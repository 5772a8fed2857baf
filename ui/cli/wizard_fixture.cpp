#include "cli/wizard_fixture.h"

#include <algorithm>

#include <fmt/core.h>

#include "accelcal/acquire/source/sensor_set_spec.h"
#include "accelcal/app/fixture/fixture_finish.h"
#include "accelcal/app/fixture/sensor_batch.h"
#include "accelcal/base/error.h"
#include "accelcal/base/sensor_columns.h"
#include "accelcal/io/fixture_file.h"

namespace accelcal::cli {
namespace {

// Each sensor's samples kept for this long behind the newest (a capture's span and a margin), s.
double KeepS(const Procedure& procedure) {
  double longest_s = 0.0;
  for (const ProcedureStep& s : procedure.steps) longest_s = std::max(longest_s, s.duration_s);
  return longest_s + 15.0;
}

// The lead a resumed session recorded (its serial), as an index; -1 when none.
int RecordedLead(const SessionJournal& session, const Fixture& fixture) {
  const SessionInputs inputs = session.Inputs();
  const auto at = inputs.find(kFixtureStepId);
  if (at == inputs.end()) return -1;
  const auto lead = at->second.find(kFixtureLeadKey);
  if (lead == at->second.end()) return -1;
  for (std::size_t i = 0; i < fixture.sensors.size(); ++i)
    if (fixture.sensors[i].serial == lead->second) return static_cast<int>(i);
  return -1;
}

}  // namespace

bool WantsFixture(const WizardCommandOptions& options) {
  if (options.sensors > 1 || !options.fixture_path.empty()) return true;
  if (options.columns.empty()) return false;
  std::string error;
  return SplitSensorColumns(options.columns, &error).size() > 1;
}

FixtureWizard OpenFixtureWizard(const WizardCommandOptions& options, const SourceOptions& source_options,
                                const Procedure& procedure, SessionJournal& session,
                                std::function<void(const std::string&)> notice) {
  SensorSetRequest request;
  request.sensors = options.sensors;
  request.columns = options.columns;
  if (!options.fixture_path.empty()) request.fixture = LoadFixture(options.fixture_path);
  std::unique_ptr<SensorSetSource> set = OpenSensorSet(options.source, source_options, request);
  const int lead = RecordedLead(session, set->fixture());
  FixtureWizard fixture;
  fixture.source = std::make_unique<FixtureLeadSource>(std::move(set), KeepS(procedure), 2.0, lead);
  fixture.journal = std::make_unique<FixtureJournal>(session, *fixture.source, procedure, std::move(notice));
  return fixture;
}

void FinishFixtureWizard(const FixtureWizard& fixture, SessionJournal& session,
                         const Procedure& procedure, const std::string& procedure_path,
                         const std::string& session_path, std::ostream& out) {
  const FixtureFinish finish = FinishFixtureSession(session, fixture.source->lead(), procedure,
                                                    procedure_path, session_path);
  for (const std::string& line : finish.lines) out << line << "\n";
}

}  // namespace accelcal::cli
