#include "accelcal/app/wizard/wizard_view.h"

namespace accelcal {

std::string_view WizardScreenToString(WizardScreen screen) {
  switch (screen) {
    case WizardScreen::kWelcome: return "welcome";
    case WizardScreen::kLevel: return "level";
    case WizardScreen::kPlacePose: return "place_pose";
    case WizardScreen::kMountTurntable: return "mount_turntable";
    case WizardScreen::kInput: return "input";
    case WizardScreen::kCapturing: return "capturing";
    case WizardScreen::kRecording: return "recording";
    case WizardScreen::kFit: return "fit";
    case WizardScreen::kDiagnosis: return "diagnosis";
    case WizardScreen::kReport: return "report";
    case WizardScreen::kDone: return "done";
    case WizardScreen::kError: return "error";
  }
  return "?";
}

}  // namespace accelcal
