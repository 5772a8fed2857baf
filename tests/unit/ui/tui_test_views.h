// Wizard views the TUI tests render and drive (tests/unit/tui_*_test.cpp).
#pragma once

#include <cmath>
#include <string>

#include "accelcal/app/wizard/wizard_view.h"

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

// A 12-hour drift record 3 h 12 min 5 s in, resumed once, one knock seen; the drift has a
// warm-up on x, a slope on y and a slow wave on z. The Allan curves are empty.
inline WizardView RecordingView() {
  WizardView v = BaseView();
  v.procedure = "Drift record: 12 hours static, z up";
  v.step_index = 2;
  v.step_count = 2;
  v.resumed = true;
  v.screen = WizardScreen::kRecording;
  v.step_title = "Static record for the drift analysis";
  v.prompt = "Resuming the Static record for the drift analysis: 3 h 11 min recorded, gap of 42 s; "
             "recording 03:12:05 of 12:00:00";
  v.pose_name = "+z up";
  v.expected_up = Eigen::Vector3d(0, 0, 1);
  v.live_counts = Eigen::Vector3d(2051.0, 2040.0, 2401.0);
  v.live_g = 1.0004;
  v.progress = 11525.0 / 43200.0;
  v.stability_text = "moved 1 time (last at 01:02:03, 41 counts on x); the record goes on";
  v.keys = {{"s", "skip"}, {"b", "back"}, {"q", "save and quit"}};
  RecordView r;
  r.elapsed_s = 11525.0;
  r.duration_s = 43200.0;
  r.gaps = 1;
  r.gaps_s = 42.0;
  r.recorded_s = r.elapsed_s - r.gaps_s;
  r.samples = 1148300;
  r.chunks = 1148;
  r.bumps = 1;
  r.last_bump = "at 01:02:03, 41 counts on x";
  r.drift_bin_s = 216.0;
  for (int i = 0; i * 216.0 < r.elapsed_s; ++i) {
    const double t = (i + 0.5) * 216.0;
    r.drift.push_back({t, Eigen::Vector3d(0.8 * (1.0 - std::exp(-t / 3000.0)), -0.3 * t / 11525.0,
                                          0.2 * std::sin(t / 2000.0))});
  }
  v.record = r;
  return v;
}

// The same record with Allan curves: white noise (slope -1/2) turning into drift (+1/2).
inline WizardView RecordingWithAllanView() {
  WizardView v = RecordingView();
  for (int axis = 0; axis < 3; ++axis) {
    for (double tau = 0.01; tau < 2000.0; tau *= 2.0) {
      const double adev = (1.5 + 0.1 * axis) / std::sqrt(tau * 100.0) + 0.002 * (axis + 1) * std::sqrt(tau);
      v.record->allan[static_cast<size_t>(axis)].push_back({tau, adev});
    }
  }
  return v;
}

}  // namespace accelcal::testing
