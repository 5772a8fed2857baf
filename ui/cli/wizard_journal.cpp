#include "cli/wizard_journal.h"

#include "accelcal/session/session_store.h"

namespace accelcal::cli {

// The SQLite store: created when absent, resumed when present; refused (with the holder's pid)
// while another accelcal has it open.
std::unique_ptr<SessionJournal> OpenWizardJournal(const std::string& session_path,
                                                  const std::string& procedure,
                                                  const std::string& source) {
  SessionOpenOptions options;
  options.procedure = procedure;
  options.source = source;
  return SessionStore::Open(session_path, options);
}

}  // namespace accelcal::cli
