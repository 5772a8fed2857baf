#include "cli/wizard_fixture.h"

#include <algorithm>

#include <fmt/core.h>

#include "accelcal/acquire/source/remote_bench.h"
#include "accelcal/app/device/vehicle_imus_writeback.h"
#include "accelcal/acquire/source/sensor_set_spec.h"
#include "accelcal/app/fixture/fixture_finish.h"
#include "accelcal/app/fixture/sensor_batch.h"
#include "accelcal/base/error.h"
#include "accelcal/base/sensor_columns.h"
#include "accelcal/io/fixture_file.h"

namespace accelcal::cli {
namespace {

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

std::unique_ptr<SensorSetSource> OpenWizardSensorSet(const WizardCommandOptions& options,
                                                     const SourceOptions& source_options) {
  SensorSetRequest request;
  request.sensors = options.sensors;
  request.columns = options.columns;
  if (!options.fixture_path.empty()) request.fixture = LoadFixture(options.fixture_path);
  return OpenSensorSet(options.source, source_options, request);
}

FixtureWizard OpenFixtureWizard(std::unique_ptr<SensorSetSource> set, const WizardCommandOptions& options,
                                const Procedure& procedure, SessionJournal& session,
                                std::function<void(const std::string&)> notice) {
  MavlinkSensorSet* vehicle = dynamic_cast<MavlinkSensorSet*>(set.get());
  // The virtual bench behind a real link (a test vehicle's IMUs): its controls move them all.
  if (!options.bench_control.empty())
    set = WithRemoteBench(std::move(set), ParseHostPort(options.bench_control, options.bench_control,
                                                        "--bench-control HOST:PORT"));
  const int lead = RecordedLead(session, set->fixture());
  FixtureWizard fixture;
  fixture.vehicle = vehicle;
  fixture.source = std::make_unique<FixtureLeadSource>(std::move(set), FixtureKeepS(procedure), 2.0, lead);
  fixture.journal = std::make_unique<FixtureJournal>(session, *fixture.source, procedure, std::move(notice));
  return fixture;
}

void FinishFixtureWizard(const FixtureWizard& fixture, SessionJournal& session,
                         const Procedure& procedure, const std::string& procedure_path,
                         const std::string& session_path, std::ostream& out) {
  const FixtureFinish finish = FinishFixtureSession(session, fixture.source->lead(), procedure,
                                                    procedure_path, session_path);
  for (const std::string& line : finish.lines) out << line << "\n";
  if (fixture.vehicle == nullptr || finish.batch.empty()) return;
  MavlinkSource& imus = fixture.vehicle->instances();
  std::vector<ImuWriteback> each;
  for (const SensorBatchRow& row : finish.batch) {
    const auto lane = static_cast<std::size_t>(row.sensor);
    each.push_back({imus.imu(lane), row.sensor + 1, row.serial, row.verdict, row.calibration, row.reason,
                    imus.undo(lane).has_value()});
  }
  for (const std::string& line : ImuWritebackLines(session_path, imus.spec(), procedure_path, each))
    out << line << "\n";
}

}  // namespace accelcal::cli
