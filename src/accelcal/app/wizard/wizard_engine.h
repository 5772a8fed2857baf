// The wizard engine: the calibration procedure (procedure.h) as a sequence of steps over a live
// sample source, recording everything accepted in a session journal. No terminal code: front
// ends (ui/) drive it through WizardDriver (Poll / Handle / View).
//
// Each step is run by its kind's controller (step_controller.h; steps/: the welcome first, then
// level, static, turntable, record, fit, diagnosis, report, analysis), which owns what belongs
// to the step: its questions and phases, its view and words, what it records and how it resumes.
// What the steps share (the procedure, the source, the session model, the gravity, the noise
// floor, the clock, the acquisition, the calibration steps, the screen's messages) is the
// session's (wizard_session.h), owned here. The engine sequences the steps and owns what
// crosses them:
//
// - Skipping a step asks first (s again skips, Enter keeps the step): a skipped required step
//   makes the report INCOMPLETE; the fit and the report cannot be skipped.
// - Back (b), when the step goes no further back within itself, goes to the nearest earlier
//   step that keeps a capture or a record: one without is entered; an accepted static or
//   turntable capture is offered to be taken again (a redo, asked first: Enter takes it again, b
//   looks further back, n keeps it). The redo's capture supersedes the old one when it is
//   accepted (both stay in the session: SessionJournal::RecordRedoCapture); b or s before then,
//   or q, keeps the old one (wizard_engine_redo.cpp).
// - q saves and leaves at any moment.
// - Resume: on construction the journal is read (each step's controller reads its part):
//   recorded steps are skipped and the wizard continues at the first missing one, with a
//   summary of what the session holds. A finished session opened again offers a refit with
//   new inputs (a corrected gravity, equipment or identification: app/refit_session.h); Enter
//   leaves it as it is.
//
// Journal contract: an accepted capture is recorded (RecordCapture) before the wizard moves on,
// inputs with RecordInput, finished steps without a capture with RecordStepDone, so quitting or
// dying at any moment loses only the capture in progress.
//
// Time: every sample is put on one session clock (session_clock.h): a resumed run continues
// after the last recorded sample, with the gap stated. Time comes from the samples' t (the
// simulator may run faster than real time).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "accelcal/acquire/source/sample_source.h"
#include "accelcal/app/refit_session.h"
#include "accelcal/app/wizard/session_model.h"
#include "accelcal/app/wizard/source_notices.h"
#include "accelcal/app/wizard/step_controller.h"
#include "accelcal/app/wizard/steps/welcome_step.h"
#include "accelcal/app/wizard/wizard_driver.h"
#include "accelcal/app/wizard/wizard_options.h"
#include "accelcal/app/wizard/wizard_outputs.h"
#include "accelcal/app/wizard/wizard_session.h"
#include "accelcal/session/procedure.h"
#include "accelcal/session/session_journal.h"

namespace accelcal {

class WizardEngine final : public WizardDriver, private StepSequence {
 public:
  // Borrows `source` and `journal`: both must outlive the engine. Throws accelcal::Error for
  // invalid options, and for a step whose kind has no controller.
  WizardEngine(Procedure procedure, SampleSource& source, SessionJournal& journal,
               WizardOptions options);
  ~WizardEngine() override;

  void Poll(double timeout_s) override;
  void Handle(const Intent& intent) override;
  WizardView View() const override;
  // True once every step of the procedure is done (not merely left with q).
  bool completed() const { return flow_ == Flow::kDone && !quit_; }
  // True when the session was left at a dead end (a fit refused, a capture refused again and
  // again: SaveAndLeave), not by the technician's q: saved, but the job failed (exit status 1).
  bool left_on_failure() const { return flow_ == Flow::kDone && left_on_failure_; }

 private:
  enum class Flow {
    kStep,         // the current step (the welcome included) is on screen
    kConfirmSkip,  // s was pressed: asking before the step is skipped
    kConfirmRedo,  // b reached an accepted capture: asking before it is taken again
    kOfferRefit,   // a finished session opened again: "Refit with new inputs?" (Enter: no)
    kDone,         // finished or left
  };

  const ProcedureStep& step() const { return procedure_.steps[static_cast<size_t>(current_)]; }
  bool InSteps(int index) const { return index >= 0 && index < static_cast<int>(procedure_.steps.size()); }
  // The current step's controller: the welcome's before the steps; nullptr once they are done.
  StepController* Current();
  const StepController* Current() const;
  void ReadJournal();
  void EnterStep(int index);
  bool LeftOutByPlan();
  void AdvanceFrom(int index);
  void Quit();
  void HandleConfirmSkip(const Intent& intent);
  void HandleOfferRefit(const Intent& intent);
  void UpdateLive(const std::vector<Sample>& chunk);

  // StepSequence: what the steps ask of the engine.
  void FinishStep(const std::string& outcome) override;
  void ContinueFromFirstOpenStep() override;
  void RestartStep() override { EnterStep(current_); }
  void AskSkip() override;
  void GoBack() override;
  void SaveAndLeave() override {
    Quit();
    left_on_failure_ = true;
  }
  void RetakeStep(const std::string& step_id) override;
  void RecordCapture(const Capture& capture) override;
  int ReplacedCaptureId() const override { return Redoing() ? redo_capture_id_ : 0; }
  double SessionLeftS(bool current_started) const override;

  // Redo of an accepted capture (wizard_engine_redo.cpp).
  const JournalCapture* RedoableCapture(const ProcedureStep& s) const;
  void AskRedo(int step_index);
  void HandleConfirmRedo(const Intent& intent);
  void StartRedo();
  void CancelRedo();
  bool Redoing() const { return !redo_of_.empty(); }
  void SetConfirmRedoView(WizardView& v) const;
  void AddRedoLines(WizardView& v) const;

  // The view (wizard_engine_view.cpp).
  void SetStepView(WizardView& v) const;
  void SetFlowView(WizardView& v) const;
  void SetConfirmSkipView(WizardView& v) const;
  void SetDoneView(WizardView& v) const;
  void SetOfferRefitView(WizardView& v) const;
  void SetRefittedView(WizardView& v) const;
  void SetTimeView(WizardView& v) const;

  Procedure procedure_;
  SessionModel model_;  // the session in memory; writes go through to the borrowed journal
  WizardOptions options_;
  std::unique_ptr<WizardOutputs> outputs_;  // files beside the session; null: none written
  WizardSession session_;
  WelcomeStep welcome_;
  std::vector<std::unique_ptr<StepController>> controllers_;  // one per procedure step
  SourceNotices source_notices_;  // what the source noticed, in the bench's words

  int current_ = -1;  // -1: the welcome; steps.size(): done
  Flow flow_ = Flow::kStep;
  bool resumed_ = false;
  std::vector<std::string> resume_lines_;  // what the journal held at construction
  bool clock_noted_ = false;
  bool opened_again_ = false;  // a finished session's step entered again (OpensAgainAtEnd)
  bool quit_ = false;
  bool left_on_failure_ = false;  // quit at a dead end (SaveAndLeave), not by q
  std::vector<std::string> plan_skipped_;  // the steps of the run of plan skips being said
  std::string notice_before_skips_;        // what the screen said before them
  std::string refit_error_;             // kOfferRefit: why the last answer was refused
  std::optional<RefitOutcome> refit_;   // the refit made at the end of this run, if any

  int redo_target_ = -1;     // kConfirmRedo: the step offered to be taken again
  int retake_return_ = -1;   // a retake asked by a step (RetakeStep): the step to come back to
  std::string redo_of_;      // a redo runs: the journal step id of the capture it supersedes
  int redo_capture_id_ = 0;  // ... and that capture's id
  std::string redo_note_;          // what the last redo did, shown until the next capture
  size_t redo_note_captures_ = 0;  // the number of captures when it was said
};

}  // namespace accelcal
