// What a front end drives: the wizard engine seen through three calls. The ncurses TUI and the
// plain line mode (ui/) each run one loop over it; neither knows anything else of the engine.
#pragma once

#include "accelcal/app/wizard/wizard_view.h"

namespace accelcal {

class WizardDriver {
 public:
  virtual ~WizardDriver() = default;
  // Reads what the sample source has (waiting at most timeout_s of wall time) and advances the
  // wizard: captures progress, checks run, steps complete. Never blocks longer.
  virtual void Poll(double timeout_s) = 0;
  // The operator's intent; the view changes accordingly.
  virtual void Handle(const Intent& intent) = 0;
  // The current view-model (a copy: the front end keeps nothing else).
  virtual WizardView View() const = 0;
};

}  // namespace accelcal
