// The wizard engine: the calibration procedure (procedure.h) as a state machine over a live
// sample source, recording everything accepted in a session journal. No terminal code: front
// ends (ui/) drive it through WizardDriver (Poll / Handle / View).
//
// Steps: welcome (device serial, operator), then the procedure's steps in order: level (reversal
// method), static poses and long records (capture engine: settling, retry after a bump, wrong
// face refused), turntable runs (radius and rpm asked, checked against the range), fit,
// diagnosis (asks before adopting), report (the calibration JSON is the journal's result).
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
  GravitySpec gravity;                   // local gravity for the fit and the checks
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
    kWelcome,      // an input of the welcome (device, operator)
    kQuiet,        // measuring the noise floor
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
  void OnAcquisition(AcquisitionEvent event);
  bool RecordResumable() const;
  void OnCaptureAccepted();
  void OnLevelCapture(const Eigen::Vector3d& mean_counts);
  void FinishStep(const std::string& outcome);
  void SkipStep();
  void GoBack();
  void Quit();
  void HandleWelcome(const Intent& intent);
  // The welcome's questions in order: {input key, label, default}.
  struct WelcomeField {
    const char* key;
    const char* label;
    const std::string& default_value;
  };
  WelcomeField Welcome(int field) const;
  void HandleTurntableInput(const Intent& intent);
  void HandleResult(const Intent& intent);
  void HandleCaptureIntent(const Intent& intent);
  void Show(StepOutcome outcome);
  void RunFit();
  void RunDiagnosis();
  void RunReport();
  void RunAnalysis();
  void UpdateLive(const std::vector<Sample>& chunk);
  void SetStepView(WizardView& v) const;
  void SetPhaseView(WizardView& v) const;
  // The view of each phase (wizard_engine_view.cpp).
  void SetWelcomeView(WizardView& v) const;
  void SetQuietView(WizardView& v) const;
  void SetPlaceView(WizardView& v) const;
  void SetLevelView(WizardView& v) const;
  void SetInputView(WizardView& v) const;
  void SetResultView(WizardView& v) const;
  void SetDoneView(WizardView& v) const;
  void SetCaptureView(WizardView& v) const;
  void SetRecordView(WizardView& v) const;

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
  std::string problem_;
  std::string hint_;
  std::vector<std::string> lines_;
  bool resumed_ = false;
  std::vector<std::string> resume_lines_;  // what the journal held at construction
  bool progressed_ = false;                // this run has recorded a step or capture
  bool quit_ = false;

  StepAcquisition acq_;  // the noise floor, the capture or the record being acquired
  std::vector<CapturedPose> captured_;
  int next_capture_id_ = 1;

  std::optional<Eigen::Vector3d> level_first_counts_;
  Eigen::Vector2d level_tilt_deg_ = Eigen::Vector2d::Constant(kNaN);
  bool level_ok_ = false;

  double radius_m_ = kNaN;
  double rpm_ = kNaN;

  bool adopt_effects_ = true;
  std::string analysis_outcome_;  // the analysis step's figures, for the journal

  Eigen::Vector3d live_counts_ = Eigen::Vector3d::Constant(kNaN);
};

}  // namespace accelcal
