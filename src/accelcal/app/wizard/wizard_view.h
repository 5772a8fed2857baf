// The wizard's view-model and intents: the whole contract between the wizard engine (src/,
// no terminal code) and its front ends (ui/: ncurses and plain line mode). A front end draws a
// WizardView and sends Intents back; it keeps no calibration state of its own (docs/STYLE.md:
// FTXUI's state/drawing split, htop's single loop).
//
// Units: live readings in raw counts and in g (approximate, from the nominal model until the
// fit), progress and stability as fractions.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"

namespace accelcal {

// What the current step is about; a front end may pick its drawing from it.
enum class WizardScreen {
  kWelcome,         // session and procedure, "resuming" when it is
  kLevel,           // level the table (tilt in two axes, reversal method)
  kPlacePose,       // put the prism on a face / in a tilted pose
  kMountTurntable,  // mount on the turntable; radius and rpm asked
  kInput,           // a value is asked (radius, rpm, operator, ...)
  kCapturing,       // a capture is running (progress, stability)
  kRecording,       // a record step runs (elapsed, drift plot, Allan curve)
  kFit,             // the fit's result
  kDiagnosis,       // the diagnosis: effects proposed, asks before adopting
  kReport,          // the printed calibration report
  kDone,            // finished; the session is closed
  kError,           // a condition the operator must see (dead link, ...)
};

std::string_view WizardScreenToString(WizardScreen screen);

struct KeyHint {
  std::string key;     // as shown: "Enter", "r", "s", "b", "q"
  std::string action;  // "accept", "retry", "skip", "back", "save and quit"
};

// A value the step asks for. The front end shows `label`, the `default_text` (taken on an empty
// answer) and, after a refused answer, `error` (why, in words).
struct InputRequest {
  std::string key;           // e.g. "radius", "rpm", "operator"
  std::string label;         // e.g. "Radius from the spin axis to the sensor (e.g. 120 mm)"
  std::string default_text;  // may be empty
  std::string error;         // why the last answer was refused; empty when none
};

// One point of the drift plot: the mean of each axis over one bin of the record, minus the
// mean of the record's first minute, counts.
struct DriftPoint {
  double t_s = 0.0;  // middle of the bin, from the record's first sample, s
  Eigen::Vector3d drift_counts = Eigen::Vector3d::Zero();
};

// One point of an Allan deviation curve.
struct AllanCurvePoint {
  double tau_s = 0.0;        // averaging time, s
  double adev_counts = 0.0;  // Allan deviation, counts
};

// A record step (noise, drift) while it runs: time on the record's clock (gaps included).
struct RecordView {
  double elapsed_s = 0.0;     // from the first sample to the latest, gaps included, s
  double duration_s = 0.0;    // what the step records, s
  double recorded_s = 0.0;    // elapsed_s minus the gaps, s
  long samples = 0;           // recorded so far (committed and in the chunk being filled)
  long chunks = 0;            // committed chunks
  long gaps = 0;
  double gaps_s = 0.0;        // total length of the gaps, s
  long bumps = 0;             // movements seen (a reading far from the running mean)
  std::string last_bump;      // "at 03:12:05, 41 counts on x"; empty when none
  double drift_bin_s = 0.0;   // width of the drift plot's bins, s
  std::vector<DriftPoint> drift;  // in time order; bins without samples (gaps) are absent
  // The Allan deviation so far, per axis (x, y, z), tau increasing, counts: RecordStepWriter's
  // streaming record analysis (analysis/record_analysis.h) of every recorded sample, gaps
  // declared missing. Empty until the record holds a few averaging times.
  std::array<std::vector<AllanCurvePoint>, 3> allan;
};

struct WizardView {
  std::string session;        // session name or file
  std::string procedure;      // procedure title
  bool resumed = false;       // this run continues an interrupted session
  int step_index = 0;         // 1-based
  int step_count = 0;
  std::string step_title;     // "Prism: +z up (pose 1 of 9)"
  WizardScreen screen = WizardScreen::kWelcome;
  std::string prompt;         // what to do now, in words

  // The pose asked for: the expected "up" direction in the sensor frame (unit), and its name.
  std::optional<Eigen::Vector3d> expected_up;
  std::string pose_name;      // "+z up", "tilted +x+y+z", "x radial, z up"

  // Live reading (NaN when there is none yet).
  Eigen::Vector3d live_counts = Eigen::Vector3d::Constant(kNaN);
  double live_g = kNaN;           // |f| in g, from the nominal model (approximate before the fit)
  Eigen::Vector2d tilt_deg = Eigen::Vector2d::Constant(kNaN);  // leveling: about x and y
  // Leveling: what the live tilt holds: "includes the sensor's offset until the reversal", then
  // "sensor's offset (x 1.5, y -0.2 deg) taken out" (at most 48 characters).
  std::string tilt_note;
  double stability = kNaN;        // 0 = still ... >= 1 = beyond the limit (worst axis)
  std::string stability_text;     // "still", "moving: x std 4.1 counts, limit 2.5"
  double progress = kNaN;         // 0..1 during a capture
  std::optional<RecordView> record;  // a record step is running (screen kRecording)
  // The session's noise floor, per axis, and where it came from ("x 1.52  y 1.49  z 1.71
  // counts (quiet period of 2.0 s, 200 samples)"); empty before it is measured.
  std::string noise_floor_text;

  std::string problem;            // what failed, in words; empty when nothing did
  std::string hint;               // what to do about it
  std::optional<InputRequest> input;
  std::vector<std::string> lines; // fit, diagnosis or report text (80 columns)
  std::vector<KeyHint> keys;      // the keys that mean something now

  // The capture flow in the technician's terms (capture_messages.h, time_estimate.h,
  // final_summary.h). `stability_text` and `problem` say in plain words what the bench needs;
  // the statistics behind them are here, for a detail line (line mode) or one key away (TUI).
  std::string detail;             // "spike: z jumped -231 counts (135.1 sigma) at t = 9.64 s"; may be empty
  bool waiting = false;           // the normal settling after letting go: a wait, not a warning
  // Time: this capture's seconds left (NaN before it captures), the countdown to its give-up
  // (NaN: none), the session's estimated time left (NaN: none), and all three in words.
  double capture_left_s = kNaN;
  double give_up_in_s = kNaN;
  double session_left_s = kNaN;
  std::string time_text;          // "4 s left of this capture; gives up in 52 s; session: about 14 min left (estimate)"
  // An accepted capture confirmed with its figures, shown on the next screen until a key:
  // "+z up done: 10.0 s, |a| ~10.12 m/s^2 by the datasheet, noise 1.6 counts". Empty when none.
  std::string notice;
  // The final screen: the report's verdict ("PASS", "FAIL", "INCOMPLETE", "NO LIMITS STATED");
  // `lines` then hold the summary (limits failed, headline numbers, report paths). Empty before.
  std::string verdict;
  std::string status;             // the source's brief status ("sim: up, 100.0 Hz, ...")
  // What the source noticed, in the bench's words ("The device restarted ..."; source_notices.h),
  // until the next key; and the figures behind it (the source's own words, its counts), one key
  // away. Empty when there is nothing to say.
  std::string source_notice;
  std::string source_detail;
  bool finished = false;          // nothing more to do; the front end may exit
};

enum class IntentKind {
  kAccept,      // Enter: accept / continue / take the default
  kRetry,       // r
  kSkip,        // s
  kBack,        // b
  kQuit,        // q: save and leave (always allowed)
  kSubmitText,  // an answer to the current InputRequest (text may be empty: the default)
  kAnswerNo,    // n: decline (e.g. do not adopt the proposed effect)
  kDetails,     // d: show or hide the statistics behind a result (the diagnosis's tables)
};

struct Intent {
  IntentKind kind = IntentKind::kAccept;
  std::string text;  // kSubmitText only
};

}  // namespace accelcal
