// `accelcal wizard --sensors N | --fixture FILE`: the wizard on several sensors at once
// (issue 31; app/fixture/fixture_capture.h says how): the lead sensor and the fixture's journal
// that the engine is given, and the per-sensor end of the session.
#pragma once

#include <functional>
#include <memory>
#include <ostream>
#include <string>

#include "accelcal/acquire/mavlink/mavlink_sensor_set.h"
#include "accelcal/acquire/source/source_options.h"
#include "accelcal/app/fixture/fixture_capture.h"
#include "accelcal/session/procedure.h"
#include "cli/wizard.h"

namespace accelcal::cli {

// True when the options ask for several sensors (--sensors above 1, --fixture, or --columns
// naming more than one sensor).
bool WantsFixture(const WizardCommandOptions& options);

struct FixtureWizard {
  std::unique_ptr<FixtureLeadSource> source;
  std::unique_ptr<FixtureJournal> journal;
  // A vehicle's IMUs over one MAVLink link (inside source), borrowed: its end names the
  // write-back of each IMU. nullptr for any other set.
  MavlinkSensorSet* vehicle = nullptr;
};

// The sensors the options ask for (before any session is opened: a vehicle's IMUs have their
// calibration read first). Throws accelcal::Error for a set that cannot be opened.
std::unique_ptr<SensorSetSource> OpenWizardSensorSet(const WizardCommandOptions& options,
                                                     const SourceOptions& source_options);

// Takes the sensors (a resumed session keeps its lead) and wraps `session`. Throws
// accelcal::Error for a fixture that cannot run (no sensor can lead, counts that disagree).
FixtureWizard OpenFixtureWizard(std::unique_ptr<SensorSetSource> set, const WizardCommandOptions& options,
                                const Procedure& procedure, SessionJournal& session,
                                std::function<void(const std::string&)> notice);

// After the engine's report: every sensor calibrated, reported, and the batch summary; for a
// vehicle's IMUs, the command that writes each into the vehicle (vehicle_imus_writeback.h).
void FinishFixtureWizard(const FixtureWizard& fixture, SessionJournal& session,
                         const Procedure& procedure, const std::string& procedure_path,
                         const std::string& session_path, std::ostream& out);

}  // namespace accelcal::cli
