#include "cli/wizard_journal.h"

namespace accelcal::cli {

// Replaced by the SQLite store at merge (src/accelcal/session/session_store.h): until then a
// session lives only as long as the process, and `session_path` is only its name.
std::unique_ptr<SessionJournal> OpenWizardJournal(const std::string& /*session_path*/) {
  return MakeMemoryJournal();
}

}  // namespace accelcal::cli
