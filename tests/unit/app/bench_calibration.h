// A wizard-like calibration on the default virtual bench with its uncertainty budget, as the
// report step makes it (the report's inputs), for the certificate's and the verdict's tests.
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/virtual_bench.h"
#include "accelcal/app/calibration_pipeline.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/report/report_model.h"

namespace accelcal::testing {

// The procedure of `equipment` (its [equipment] tables), with a single fit step.
inline Procedure ProcedureWithEquipment(const std::string& equipment) {
  return ParseProcedure("title = \"t\"\n[sensor]\nnominal_scale_counts_per_mps2 = 34.8\n"
                        "nominal_bias_counts = 2048\n" + equipment +
                        "\n[[step]]\nid = \"fit\"\nkind = \"fit\"\n", "test.toml");
}

// The default bench's 18 captures (seed 7) calibrated with `gravity` and the uncertainties of
// `equipment`; the diagnosis off (the base model).
inline ReportInputs BenchInputs(const std::vector<EquipmentItem>& equipment,
                                GravitySpec gravity = GravitySpec::Given(9.80665, 0.0002)) {
  sim::Scenario scenario = sim::DefaultScenario();
  scenario.bench.seed = 7;
  sim::VirtualBench bench(scenario);
  CalibrationRequest request;
  request.captures = bench.SimulateCaptureSet();
  request.source_name = "bench";
  request.gravity = gravity;
  request.screening.adc_range = scenario.adc.Range();
  request.diagnose = false;
  request.references = ToReferenceUncertainties(equipment, kNaN);
  const CalibrationOutcome outcome = CalibrateCaptures(request);
  EXPECT_TRUE(outcome.usable());
  ReportInputs in;
  in.calibration = outcome.MakeCalibration(true);
  in.meta.session_name = "20261123T211200Z";
  in.meta.source = "sim";
  in.meta.procedure = "Full calibration";
  in.equipment = equipment;
  in.nominal_bias_counts = Eigen::Vector3d::Constant(2048.0);
  in.nominal_scale_counts_per_mps2 = Eigen::Vector3d::Constant(34.8);
  return in;
}

}  // namespace accelcal::testing
