// One clock for the whole session, across resumes. A source's t restarts when the program does
// (the simulator's at 0, a board's at its boot), so a resumed session's captures would go back
// in time: `accelcal export` then writes a capture set `accelcal fit` refuses, and the effects
// of time (drift) see meaningless times. The wizard puts every sample on the session clock:
//
//   first run            t_session = t_source
//   a resumed run        t_session = t_source + offset, offset chosen once, at the run's first
//                        sample, so that it comes `gap` after the last t the session holds
//                        (its captures' and records' last samples); gap = the computer's clock
//                        from the last accepted capture (or record chunk) to now (at least
//                        kMinGapS). A source whose t already runs on past the session's last
//                        (a board's clock that did not restart) is left as it is.
//
// The last accepted capture's t and wall time are recorded in the journal (input
// "last_capture" of the pseudo step kClockStep), and each resume's shift too (input "resume N":
// "t 1017.21 s -> 1059.30 s, a gap of 42.1 s on the computer's clock"), so the gap is stated.
// A record's own clock (record_step_writer.h) goes on as before: it sees session times.
//
// Units: s (session clock, and seconds since the Unix epoch for the computer's clock).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "accelcal/app/wizard/session_model.h"
#include "accelcal/base/capture.h"
#include "accelcal/session/session_inputs.h"

namespace accelcal {

class SessionClock {
 public:
  static constexpr const char* kClockStep = kSessionClockStepId;  // its keys: session_inputs.h
  static constexpr double kMinGapS = 1.0;

  // The session time at which a resumed run's clock goes on, from its "resume N" input as
  // recorded (t_first_source_s + offset_s(): the run's first sample); nullopt when it does not
  // read. With the source's own t of that first sample it gives the run's offset to whoever
  // sees the source's samples before the clock does (app/fixture: the other sensors').
  static std::optional<double> ResumedAtS(const std::string& resume_value);

  // Reads what the session holds. `wall_now_s`: the computer's clock (s since the epoch).
  SessionClock(const SessionModel& model, std::function<double()> wall_now_s);

  // Moves `chunk` onto the session clock; the first chunk of a resumed run fixes the offset
  // and records it in `model` (durable).
  void Shift(std::vector<Sample>* chunk, SessionModel& model);
  // An accepted capture ending at session time t_last_s: recorded for a later resume.
  void MarkCapture(double t_last_s, SessionModel& model);

  double offset_s() const { return offset_s_; }
  // Empty, or how this run's clock joins the session's ("the session clock goes on at t =
  // 1059.30 s, after a gap of 42.1 s since the last capture (computer's clock)").
  const std::string& note() const { return note_; }

 private:
  std::function<double()> wall_now_s_;
  double last_t_s_ = kNaN;       // the session's last sample, s
  double last_wall_s_ = kNaN;    // when it was accepted (computer's clock), s
  int resumes_ = 0;              // resume notes already in the journal
  bool decided_ = false;
  double offset_s_ = 0.0;
  std::string note_;
};

}  // namespace accelcal
