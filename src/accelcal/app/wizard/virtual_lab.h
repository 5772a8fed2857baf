// What the wizard's welcome offers on the virtual bench: the scenario's lab ([lab],
// acquire/sim/scenario.h), so that a session taking every default is what a good lab does (its
// own gravity, identified and verified equipment) and its certificate can honestly PASS; a real
// bench is offered only the procedure's equipment (its example identifications keep the verdict
// INCOMPLETE until the bench's are given).
#pragma once

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/app/wizard/wizard_options.h"

namespace accelcal {

// `options` with the lab of `scenario` offered: its equipment answer, and its gravity unless the
// command line gave one (`gravity_given`: the flags' gravity stays the default answer).
void OfferVirtualLab(const sim::Scenario& scenario, bool gravity_given, WizardOptions* options);

}  // namespace accelcal
