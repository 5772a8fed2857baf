#include "accelcal/app/wizard/step_help.h"

#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/app/wizard/steps/welcome_step.h"

namespace accelcal {
namespace {

// A value asked for: what to type, in which units (said by the step that asks it).
std::string InputHelp(const std::string& key) {
  if (std::string help = WelcomeInputHelp(key); !help.empty()) return help;
  if (std::string help = StepInputHelp(key); !help.empty()) return help;
  return "Type the value asked; an empty answer takes the default shown in brackets.";
}

std::string ScreenHelp(WizardScreen screen) {
  switch (screen) {
    case WizardScreen::kWelcome:
      return "The welcome: who calibrates which device where, and the local gravity.";
    case WizardScreen::kLevel:
      return "Levelling the table: put the prism +z up and let go; the tilt is measured, then "
             "measured again after you turn the prism 180 deg about the vertical, so that the "
             "sensor's own offset cancels. Adjust the table's feet until it says level.";
    case WizardScreen::kPlacePose:
      return "Put the prism on the table with the face named above up, let go and keep your hands "
             "off the bench; press Enter. The capture waits until the sensor is still, then "
             "averages it.";
    case WizardScreen::kMountTurntable:
      return "Mount the sensor on the turntable as shown, at the radius given, start the table at "
             "the speed given and press Enter once it turns steadily.";
    case WizardScreen::kInput:
      return "A turntable run: the radius from the spin axis to the sensor, then the speed.";
    case WizardScreen::kCapturing:
      return "The program is measuring: keep your hands off the bench. It waits for the sensor "
             "to be still, then averages; a knock starts the measurement again.";
    case WizardScreen::kRecording:
      return "A long record: leave the sensor alone until the time shown. Quitting keeps what is "
             "recorded; running the wizard on the session again goes on from there.";
    case WizardScreen::kFit:
      return "The fit of the captures: read it (scroll with the arrows or PgUp/PgDn), then go on.";
    case WizardScreen::kDiagnosis:
      return "The diagnosis: effects the plain model misses, and whether to take them into the "
             "calibration. Read it, then answer.";
    case WizardScreen::kReport:
      return "The calibration report: read it, then finish.";
    case WizardScreen::kDone:
      return "Finished.";
    case WizardScreen::kError:
      return "What was done was not accepted: the reason is shown above. Fix it at the bench, "
             "then try again, skip the step or go back.";
  }
  return "";
}

}  // namespace

std::vector<std::string> StepHelp(const WizardView& view) {
  std::vector<std::string> help;
  if (!view.step_title.empty()) help.push_back("Step: " + view.step_title + ".");
  help.push_back(ScreenHelp(view.screen));
  if (view.input) help.push_back(InputHelp(view.input->key));
  help.push_back("Everything accepted is saved as it goes: quitting loses nothing, and running the "
                 "wizard on the same session resumes it.");
  return help;
}

}  // namespace accelcal
