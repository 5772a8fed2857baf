// The main of the unit-test groups from app up: the step kinds defined beside their wizard
// controllers are registered before any test reads a procedure, as the program does at its start
// (app/wizard/step_registry.h, RegisterStepKinds).
#include <gtest/gtest.h>

#include "accelcal/app/wizard/step_registry.h"

int main(int argc, char** argv) {
  accelcal::RegisterStepKinds();
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
