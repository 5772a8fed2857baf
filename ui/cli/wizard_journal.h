// Where the wizard's session journal comes from: one function, so that swapping the store is
// one file (ui/cli/wizard_journal.cpp).
#pragma once

#include <memory>
#include <string>

#include "accelcal/session/session_journal.h"

namespace accelcal::cli {

// The journal of the session file `session_path` (created when absent, resumed when present);
// `procedure` and `source` are stored when the session is created.
std::unique_ptr<SessionJournal> OpenWizardJournal(const std::string& session_path,
                                                  const std::string& procedure,
                                                  const std::string& source);

}  // namespace accelcal::cli
