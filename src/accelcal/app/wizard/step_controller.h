// One step of a wizard session, run by its kind's controller (steps/*.cpp; the welcome's is
// steps/welcome_step.h). A controller owns what belongs to its step: its state (its questions,
// its phases, what it measured), its view, its words, its time, what it records in the journal
// and how it resumes. The engine (wizard_engine.h) only sequences the steps and owns the session
// and what crosses steps: the skip's question, the way back and the redo, quitting, resuming.
//
// The engine makes one controller per procedure step when it starts (step_registry.h: the
// controller of each kind) and keeps it for the run. It is entered when its step begins (and
// again on r, on the way back, for a redo); while the step is on screen it gets the operator's
// keys (q aside) and, while it acquires, what the acquisition reports; its view is asked for on
// every View(). s and b go back to the engine (WizardSession::sequence: AskSkip, GoBack), which
// asks the controller the little it needs (BackWithin, AtStart, KeepAfterSkipDeclined, Halt).
#pragma once

#include <string>
#include <vector>

#include "accelcal/app/wizard/step_acquisition.h"
#include "accelcal/app/wizard/wizard_view.h"
#include "accelcal/session/session_journal.h"

namespace accelcal {

class StepController {
 public:
  virtual ~StepController() = default;

  // ---- the step's flow
  // The step begins (its first question or placement); the engine has stopped what ran and
  // cleared the screen's problem.
  virtual void Enter() = 0;
  // The operator's key while the step is on screen (q is the engine's).
  virtual void Handle(const Intent& intent) = 0;
  // The step takes samples now: the engine feeds them to the session's acquisition and passes on
  // what it reports (OnAcquisition).
  virtual bool Acquiring() const { return false; }
  virtual void OnAcquisition(AcquisitionEvent /*event*/) {}
  // The source ended while the step was acquiring (the engine has said so on the screen).
  virtual void OnSourceEnded() {}
  // Stops what the step runs at the bench (s asked, a redo given up).
  virtual void Halt() {}

  // ---- the way back and the skip
  // b within the step: true when it went back to its own previous question or placement.
  virtual bool BackWithin() { return false; }
  // At the step's start: b in a redo there keeps the capture the redo would replace.
  virtual bool AtStart() const { return false; }
  // s was pressed and the skip then declined: the step goes on from where it was.
  virtual void KeepAfterSkipDeclined() = 0;
  // A redo of this step's accepted capture `old` begins (after Enter).
  virtual void BeginRedo(const Capture& /*old*/) {}

  // ---- resume
  // Reads what the journal holds of the step (before anything runs).
  virtual void Resume() {}
  // The session was resumed after its last step: what the step adds to the final screen.
  virtual void RecapAtEnd() {}
  // After RecapAtEnd: the step has something to offer again and is entered instead of the final
  // screen (the report: a required run the fit left out, to take again).
  virtual bool OpensAgainAtEnd() const { return false; }

  // ---- view
  // The step's title, pose and expected up: on every screen of the step, its questions too.
  virtual void SetHeader(WizardView& v) const = 0;
  // The step's text (a result, or its statistics on d), listed before the noise floor's lines.
  virtual void AddText(std::vector<std::string>& /*lines*/) const {}
  // It shows a result (the noise floor's lines are left out beside it).
  virtual bool ShowsResult() const { return false; }
  // Its screen while it is on screen.
  virtual void SetView(WizardView& v) const = 0;
  // What the step adds to every screen while it is the current step (`on_screen`: not a question
  // of the engine's about it, a skip or a redo).
  virtual void AddLive(WizardView& /*v*/, bool /*on_screen*/) const {}
  // The capture length a waiting screen states, s; NaN when there is none to state.
  virtual double WaitingCaptureS(bool /*on_screen*/) const { return kNaN; }
  // The screen that asks for this step's placement (a redo's question about it).
  virtual WizardScreen PlaceScreen() const { return WizardScreen::kPlacePose; }
};

// A step's own keys, then skip, back and quit (always meaningful).
inline std::vector<KeyHint> WithNavigation(std::vector<KeyHint> keys) {
  keys.push_back({"s", "skip"});
  keys.push_back({"b", "back"});
  keys.push_back({"q", "save and quit"});
  return keys;
}

}  // namespace accelcal
