#include "accelcal/app/wizard/wizard_session.h"

namespace accelcal {

WizardSession::WizardSession(const Procedure& procedure_in, SampleSource& source_in, SessionModel& model_in,
                             const WizardOptions& options_in, WizardOutputs* outputs, StepSequence& sequence_in)
    : procedure(procedure_in), source(source_in), model(model_in), options(options_in), sequence(sequence_in),
      gravity(options_in.gravity),
      steps(procedure_in, model_in, options_in.gravity, options_in.session_name, outputs),
      clock(model_in, options_in.wall_now_s), acq(options_in.quiet_period_s),
      noise_floor(procedure_in, model_in, acq, screen, options_in.quiet_period_s, &source_in),
      bench_plan(procedure_in, options_in.fixed_duration_s) {}

Eigen::Vector3d WizardSession::MeasuredUp(const Capture& capture) const {
  return procedure.nominal.Calibrate(capture.stats().mean_counts).normalized();
}

}  // namespace accelcal
