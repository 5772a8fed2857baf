// Wizard views the TUI tests render and drive (tests/unit/tui_*_test.cpp).
#pragma once

#include <cmath>
#include <string>

#include "accelcal/wizard/wizard_view.h"

namespace accelcal::testing {

inline WizardView BaseView() {
  WizardView v;
  v.session = "bench-2024-05-02.db";
  v.procedure = "Prism, 6 faces + 3 tilts + turntable";
  v.step_index = 4;
  v.step_count = 14;
  v.keys = {{"Enter", "accept"}, {"r", "retry"}, {"s", "skip"}, {"b", "back"},
            {"q", "save and quit"}};
  v.status = "sim: up, 100.0 Hz, 0 dropped";
  return v;
}

inline WizardView WelcomeView() {
  WizardView v = BaseView();
  v.step_index = 1;
  v.screen = WizardScreen::kWelcome;
  v.resumed = true;
  v.step_title = "Welcome";
  v.prompt = "This session calibrates the accelerometer on the prism and the turntable. "
             "Type your name and press Enter.";
  v.input = InputRequest{"operator", "Operator name", "anonymous", ""};
  v.keys = {{"Enter", "accept"}, {"q", "save and quit"}};
  return v;
}

inline WizardView StaticPoseView() {
  WizardView v = BaseView();
  v.screen = WizardScreen::kPlacePose;
  v.step_title = "Prism: +z up (pose 3 of 9)";
  v.prompt = "Put the prism on the table with the +Z face up, hold it still, then press Enter.";
  v.expected_up = Eigen::Vector3d(0, 0, 1);
  v.pose_name = "+z up";
  v.live_counts = Eigen::Vector3d(12.4, -30.2, 1650.7);
  v.live_g = 1.0012;
  v.stability = 0.31;
  v.stability_text = "still";
  return v;
}

inline WizardView CapturingView() {
  WizardView v = StaticPoseView();
  v.screen = WizardScreen::kCapturing;
  v.prompt = "Capturing: keep the prism still.";
  v.progress = 0.62;
  v.stability = 1.4;
  v.stability_text = "moving: x std 4.1 counts, limit 2.5";
  v.keys = {{"b", "back"}, {"q", "save and quit"}};
  return v;
}

inline WizardView FailureView() {
  WizardView v = StaticPoseView();
  v.step_title = "Prism: tilted +x+y+z (pose 7 of 9)";
  v.expected_up = Eigen::Vector3d(1, 1, 1).normalized();
  v.pose_name = "tilted +x+y+z";
  v.prompt = "Put the prism on its tilted face so that +X, +Y and +Z all point up.";
  v.live_counts = Eigen::Vector3d(kNaN, kNaN, kNaN);
  v.live_g = kNaN;
  v.stability = kNaN;
  v.stability_text = "";
  v.problem = "The reading points 71 deg away from the pose asked for (-X-Y+Z seen).";
  v.hint = "Turn the prism so that the face marked +X+Y+Z is up, then press r to retry.";
  return v;
}

inline WizardView ReportView() {
  WizardView v = BaseView();
  v.step_index = 14;
  v.screen = WizardScreen::kReport;
  v.step_title = "Report";
  v.prompt = "The calibration was written to cal.json.";
  for (int i = 1; i <= 40; ++i) v.lines.push_back("report line " + std::to_string(i));
  v.keys = {};
  v.finished = true;
  return v;
}

inline WizardView TurntableView() {
  WizardView v = StaticPoseView();
  v.screen = WizardScreen::kMountTurntable;
  v.step_title = "Turntable: x radial, z up";
  v.prompt = "Mount the sensor on the turntable with +X pointing out from the spin axis.";
  v.pose_name = "x radial, z up";
  v.input = InputRequest{"radius", "Radius from the spin axis to the sensor (mm)", "120",
                         "not a number: 12o"};
  return v;
}

}  // namespace accelcal::testing
