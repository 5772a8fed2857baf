#include "cli/wizard_journal.h"

#include "accelcal/session/session_store.h"

namespace accelcal::cli {

// The SQLite store: created when absent, resumed when present; refused (with the holder's pid)
// while another accelcal has it open.
std::unique_ptr<SessionJournal> OpenWizardJournal(const std::string& session_path) {
  SessionOpenOptions options;
  options.procedure = "wizard";
  return SessionStore::Open(session_path, options);
}

}  // namespace accelcal::cli
