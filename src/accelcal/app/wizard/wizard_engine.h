// The wizard engine: the calibration procedure (procedure.h) as a state machine over a live
// sample source, recording everything accepted in a session journal. No terminal code: front
// ends (ui/) drive it through WizardDriver (Poll / Handle / View).
//
// Steps: welcome (device serial, operator, place, local gravity), then the procedure's steps
// in order: level (reversal method; on the virtual bench the technician turns the feet as
// advised), static poses and long records (capture engine: settling, retry after a bump, wrong
// face refused), turntable runs (radius and rpm asked, checked against the range; a wrong
// mounting or a tilted turntable refused with what to do), fit, diagnosis (asks before
// adopting; names the gravity ambiguity when gravity is the standard value), report (the
// calibration JSON and the session's gaps are the journal's result; the verdict says
// INCOMPLETE when a required step is missing).
//
// The local gravity is asked at the welcome: a measured value with its uncertainty, the place's
// latitude and altitude (WGS84), or "standard" said explicitly (gravity_input.h); the default
// answer is the command line's gravity, else "standard". A procedure may refuse the standard
// value, and may require the device serial and the operator.
//
// The noise floor (noise_floor_guard.h) is measured when the operator says the sensor rests
// (Enter), refused when far above the procedure's expected noise or not still, shown, and
// re-checked against each static capture: a floor that proves too high is lowered and the
// captures judged with it judged again; those that fail are left out and captured again.
//
// Skipping a step asks first (s again skips, Enter keeps the step): a skipped required step
// makes the report INCOMPLETE.
//
// Back (b) at a step's start goes to the nearest earlier capture step: a skipped one is entered;
// an accepted static or turntable capture is offered to be taken again (a redo, asked first:
// Enter takes it again, b looks further back, n keeps it). The redo's capture supersedes the old
// one when it is accepted (both stay in the session: SessionJournal::RecordRedoCapture); b or s
// before then, or q, keeps the old one (wizard_engine_redo.cpp).
//
// Time: every sample is put on one session clock (session_clock.h): a resumed run continues
// after the last recorded sample, with the gap stated.
//
// Records (kind "record": the noise and drift records) are streamed to the journal in chunks
// by RecordStepWriter (record_step_writer.h): never refused for drift, a movement is shown and the
// record goes on; q commits the chunk being filled. An interrupted record resumes where it
// stopped (without placing the sensor again) and its gap is recorded; the step is done
// (RecordStepDone with the recorded and gap times) when its duration is covered.
//
// Journal contract: an accepted capture is recorded (RecordCapture) before the wizard moves on,
// inputs with RecordInput, finished steps without a capture with RecordStepDone, so quitting or
// dying at any moment loses only the capture in progress. On construction the journal is read:
// recorded steps are skipped and the wizard continues at the first missing one.
//
// Time comes from the samples' t (the simulator may run faster than real time).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "accelcal/acquire/capture_engine/capture_engine.h"
#include "accelcal/base/gravity.h"
#include "accelcal/acquire/source/sample_source.h"
#include "accelcal/session/procedure.h"
#include "accelcal/app/wizard/calibration_steps.h"
#include "accelcal/app/wizard/record_step_writer.h"
#include "accelcal/app/wizard/noise_floor_guard.h"
#include "accelcal/app/wizard/session_clock.h"
#include "accelcal/app/wizard/session_model.h"
#include "accelcal/app/wizard/step_acquisition.h"
#include "accelcal/app/wizard/wizard_outputs.h"
#include "accelcal/session/session_journal.h"
#include "accelcal/app/wizard/wizard_driver.h"

namespace accelcal {

struct WizardOptions {
  std::string session_name = "session";  // shown in the view and in the calibration's source
  std::string default_operator;          // offered at the welcome (may be empty)
  std::string default_device;            // device serial offered at the welcome (may be empty)
  // The welcome's default gravity answer (the command line's --gravity / --latitude); the
  // standard value when none was given. What the operator answers is used for the fit and
  // the checks, and recorded in the session.
  GravitySpec gravity;
  // Before the first capture of a run the sensor rests this long to measure the noise floor,
  // s; > 0.
  double quiet_period_s = 2.0;
  // The computer's clock for record gaps, s since the Unix epoch; empty = the system clock
  // (tests give their own).
  std::function<double()> wall_now_s;
  // Non-empty: the report step also writes the calibration report beside this session file
  // (report_files.h: SESSION.report.html and SESSION.report.txt). Empty: nothing is written.
  std::string report_beside = {};
  // The lab or bench offered at the welcome (may be empty): the report's "place".
  std::string default_place = {};
  // The equipment answer offered at the welcome (equipment_input.h); empty: "keep" (the
  // procedure's). The virtual bench offers its lab's (virtual_lab.h).
  std::string default_equipment = {};
  // Said on the first screen of a session resumed (or already finished): the command line's
  // flags this run does not use, with what to do instead (app/refit_session.h).
  std::vector<std::string> notes = {};

  std::string Validate() const;
};

class WizardEngine final : public WizardDriver {
 public:
  // Borrows `source` and `journal`: both must outlive the engine. Throws accelcal::Error for
  // invalid options.
  WizardEngine(Procedure procedure, SampleSource& source, SessionJournal& journal,
               WizardOptions options);
  ~WizardEngine() override;

  void Poll(double timeout_s) override;
  void Handle(const Intent& intent) override;
  WizardView View() const override;
  // True once every step of the procedure is done (not merely left with q).
  bool completed() const { return phase_ == Phase::kDone && !quit_; }

 private:
  enum class Phase {
    kWelcome,      // an input of the welcome (device, operator, place, gravity)
    kQuietReady,   // asking the operator to leave the sensor at rest for the noise floor
    kQuiet,        // measuring the noise floor
    kConfirmSkip,  // s was pressed: asking before the step is skipped
    kConfirmRedo,  // b reached an accepted capture: asking before it is taken again
    kPlace,        // asking to place the prism / mount the turntable
    kCapture,      // the capture engine runs
    kRecord,       // a record step streams to the journal
    kProblem,      // a capture was rejected or timed out
    kLevelTurn,    // leveling: turn the prism 180 deg
    kLevelResult,  // leveling: the tilt, level or not
    kRadius,       // turntable: radius asked
    kRpm,          // turntable: rpm asked
    kResult,       // fit / diagnosis / report shown
    kDone,         // finished or left
  };

  const ProcedureStep& step() const { return procedure_.steps[static_cast<size_t>(current_)]; }
  bool StepRecorded(const std::string& id) const;
  void ReadJournal();
  void EnterStep(int index);
  void AdvanceFrom(int index);
  void EnterPlace();
  void BeginCapture();
  void StartCaptureEngine();
  void PlaceOnBench();
  CaptureRequest MakeRequest() const;
  CaptureContext MakeContext() const;
  void StartRecord();
  void FinishRecord();
  static double RecordSilenceTimeoutS(const ProcedureStep& s);
  void OnAcquisition(AcquisitionEvent event);
  bool RecordResumable() const;
  void OnCaptureAccepted();
  void OnLevelCapture(const Eigen::Vector3d& mean_counts);
  void FinishStep(const std::string& outcome);
  void SkipStep();
  void AskSkip();
  void HandleConfirmSkip(const Intent& intent);
  void GoBack();
  // Redo of an accepted capture (wizard_engine_redo.cpp).
  const JournalCapture* RedoableCapture(const ProcedureStep& s) const;
  void AskRedo(int step_index);
  void HandleConfirmRedo(const Intent& intent);
  void StartRedo();
  void CancelRedo();
  bool Redoing() const { return !redo_of_.empty(); }
  // Records an accepted capture of the current step: superseding the old one in a redo.
  void RecordAcceptedCapture(const Capture& capture);
  void SetConfirmRedoView(WizardView& v) const;
  void AddRedoLines(WizardView& v) const;
  // Noise floor (wizard_engine_capture.cpp).
  void OnQuietMeasured();
  void RecheckNoiseFloor(const Capture& latest);
  std::string CheckWelcomeAnswer(const std::string& key, const std::string& value);
  void Quit();
  void HandleWelcome(const Intent& intent);
  // The welcome's questions in order: {input key, label, default}.
  struct WelcomeField {
    const char* key;
    std::string label;
    std::string default_value;
  };
  // device, operator, place, gravity, and the equipment when the procedure lists some.
  int WelcomeFields() const { return procedure_.equipment.empty() ? 4 : 5; }
  WelcomeField Welcome(int field) const;
  // The welcome's equipment answer (recorded), applied to the calibration steps.
  void ReadEquipment();
  // The rough model's "up" of a capture (unit, platform frame).
  Eigen::Vector3d MeasuredUp(const Capture& c) const;
  void OnCaptureRejected();
  void HandleTurntableInput(const Intent& intent);
  void CorrectOtherTurntableField(const std::string& text, bool to_radius);
  void CheckTurntablePlanAndPlace(double rpm);
  void HandleResult(const Intent& intent);
  void HandleCaptureIntent(const Intent& intent);
  void Show(StepOutcome outcome);
  void RunFit();
  void RunDiagnosis();
  void RunReport();
  // A session resumed after its report step: the final summary computed again (no file written).
  void RecapReport();
  ReportMeta MetaForReport() const;
  void RunAnalysis();
  void UpdateLive(const std::vector<Sample>& chunk);
  void SetStepView(WizardView& v) const;
  void SetPhaseView(WizardView& v) const;
  // The view of each phase (wizard_engine_view.cpp).
  void SetWelcomeView(WizardView& v) const;
  void SetQuietView(WizardView& v) const;
  void SetConfirmSkipView(WizardView& v) const;
  void SetPlaceView(WizardView& v) const;
  void SetLevelView(WizardView& v) const;
  void SetInputView(WizardView& v) const;
  void SetResultView(WizardView& v) const;
  void SetDoneView(WizardView& v) const;
  void SetCaptureView(WizardView& v) const;
  void SetRecordView(WizardView& v) const;
  // Time and confirmations of the capture flow (wizard_engine_flow.cpp).
  void SetTimeView(WizardView& v) const;
  double SessionLeftS(bool current_started) const;
  void ConfirmCapture(const Capture& capture);

  Procedure procedure_;
  SampleSource& source_;    // borrowed: outlives the engine
  SessionModel model_;      // the session in memory; writes go through to the borrowed journal
  WizardOptions options_;
  std::unique_ptr<WizardOutputs> outputs_;  // files beside the session; null: none written
  CalibrationSteps steps_;  // fit, diagnosis, report, analysis

  int current_ = -1;  // -1: the welcome; steps.size(): done
  Phase phase_ = Phase::kWelcome;
  int welcome_field_ = 0;
  std::string input_error_;
  std::string input_note_;  // what a typed value set in the other turntable field
  std::string problem_;
  std::string hint_;
  std::vector<std::string> lines_;
  std::string detail_;  // the figures behind problem_ (a capture that ended unaccepted)
  std::string notice_;  // the last accepted capture, confirmed until the next key
  std::vector<std::string> details_;  // the statistics behind lines_ (d shows them)
  bool show_details_ = false;
  bool resumed_ = false;
  std::vector<std::string> resume_lines_;  // what the journal held at construction
  bool progressed_ = false;                // this run has recorded a step or capture
  bool quit_ = false;

  GravitySpec gravity_;  // the session's (the welcome's answer)
  SessionClock clock_;   // every sample on one clock across resumes
  NoiseFloorGuard floor_guard_;
  std::vector<std::string> floor_lines_;  // what the noise floor's checks said, shown
  std::optional<NoiseFloor> lowered_floor_;  // a floor lowered by the captures (this run or before)
  bool clock_noted_ = false;
  StepAcquisition acq_;  // the noise floor, the capture or the record being acquired
  std::vector<CapturedPose> captured_;
  int next_capture_id_ = 1;

  std::optional<Eigen::Vector3d> level_first_counts_;
  Eigen::Vector2d level_tilt_deg_ = Eigen::Vector2d::Constant(kNaN);
  bool level_ok_ = false;
  // The sensor's own offset measured by the last reversal (leveling.h): taken out of the live tilt.
  std::optional<Eigen::Vector2d> level_offset_;

  double radius_m_ = kNaN;
  double rpm_ = kNaN;

  bool adopt_effects_ = true;
  Phase skip_from_ = Phase::kPlace;  // the phase s was pressed in
  int redo_target_ = -1;    // kConfirmRedo: the step offered to be taken again
  std::string redo_of_;     // a redo runs: the journal step id of the capture it supersedes
  int redo_capture_id_ = 0;  // ... and that capture's id
  Phase redo_from_phase_ = Phase::kPlace;  // the phase b was pressed in
  std::string redo_note_;          // what the last redo did, shown until the next capture
  size_t redo_note_captures_ = 0;  // the number of captures when it was said
  std::string analysis_outcome_;  // the analysis step's figures, for the journal

  Eigen::Vector3d live_counts_ = Eigen::Vector3d::Constant(kNaN);
};

}  // namespace accelcal
