// Calibrations with hand-chosen parameters for the export tests (tests/unit/export_*_test.cpp).
#pragma once

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/io/calibration_file.h"

namespace accelcal::testing {

// A base-model calibration (no effects) with a visible misalignment.
inline Calibration ExportTestCalibration() {
  Calibration cal;
  cal.model.bias_counts = {2051.25, 2043.5, 2039.75};
  cal.model.scale_counts_per_mps2 = {34.1, 35.2, 34.6};
  cal.model.a_yz_rad = 0.004;
  cal.model.a_zy_rad = -0.003;
  cal.model.a_zx_rad = 0.002;
  cal.uncertainty.bias_counts = {0.05, 0.06, 0.04};
  cal.uncertainty.scale_counts_per_mps2 = {0.01, 0.012, 0.011};
  cal.uncertainty.a_yz_rad = 1e-4;
  cal.uncertainty.a_zy_rad = 1.5e-4;
  cal.uncertainty.a_zx_rad = 1.2e-4;
  cal.gravity = GravitySpec::Standard();
  cal.residual_rms_mps2 = 0.0123;
  cal.residual_max_abs_mps2 = 0.03;
  cal.source = "captures.csv";
  return cal;
}

// The same with the sensor's effects adopted (quadratic, temperature bias and scale) and one
// effect of the calibration session (radius_offset), as the diagnosis writes them.
inline Calibration ExportTestCalibrationWithEffects() {
  Calibration cal = ExportTestCalibration();
  auto effect = [](std::string name, std::vector<EffectParameter> parameters, bool corrects) {
    CalibrationEffect e;
    e.name = std::move(name);
    e.parameters = std::move(parameters);
    e.corrects_readings = corrects;
    return e;
  };
  cal.reference = {25.0, 100.0};
  cal.effects.push_back(effect("quadratic_nonlinearity",
                               {{"q_x", "counts/(m/s^2)^2", 0.02, 0.002},
                                {"q_y", "counts/(m/s^2)^2", -0.015, 0.002},
                                {"q_z", "counts/(m/s^2)^2", 0.01, 0.002}}, true));
  cal.effects.push_back(effect("temperature_scale",
                               {{"tc_scale_x", "1/degC", 1e-4, kNaN},
                                {"tc_scale_y", "1/degC", -2e-4, kNaN},
                                {"tc_scale_z", "1/degC", 5e-5, kNaN}}, true));
  cal.effects.push_back(effect("temperature_bias",
                               {{"tc_bias_x", "counts/degC", 0.5, kNaN},
                                {"tc_bias_y", "counts/degC", -0.3, kNaN},
                                {"tc_bias_z", "counts/degC", 0.2, kNaN}}, true));
  cal.effects.push_back(effect("radius_offset", {{"dr", "m", 0.0032, 0.0008}}, false));
  return cal;
}

inline std::string ExportGoldenPath(const std::string& name) {
  return std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/export/" + name;
}

// Compares `text` with tests/data/export/NAME; ACCELCAL_UPDATE_GOLDEN=1 rewrites the file.
inline void ExpectMatchesGolden(const std::string& name, const std::string& text) {
  if (const char* update = std::getenv("ACCELCAL_UPDATE_GOLDEN"); update && std::string(update) == "1") {
    std::ofstream(ExportGoldenPath(name), std::ios::binary) << text;
    return;
  }
  std::ifstream in(ExportGoldenPath(name), std::ios::binary);
  ASSERT_TRUE(in) << "missing golden file " << ExportGoldenPath(name);
  std::stringstream golden;
  golden << in.rdbuf();
  EXPECT_EQ(golden.str(), text) << name << " is now:\n" << text;
}

}  // namespace accelcal::testing
