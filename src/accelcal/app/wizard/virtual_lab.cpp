#include "accelcal/app/wizard/virtual_lab.h"

#include "accelcal/app/wizard/gravity_input.h"
#include "accelcal/base/error.h"

namespace accelcal {

void OfferVirtualLab(const sim::Scenario& scenario, bool gravity_given, WizardOptions* options) {
  options->default_equipment = scenario.lab.equipment == "keep" ? "" : scenario.lab.equipment;
  if (gravity_given) return;
  const GravityAnswer g = ParseGravityAnswer(scenario.lab.GravityAnswer(scenario.bench.gravity_mps2));
  if (!g.ok()) throw Error(scenario.source_name + ": [lab] gravity: " + g.error);
  options->gravity = g.gravity;
}

}  // namespace accelcal
