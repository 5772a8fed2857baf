// What a live sample source reports besides its samples: the state of its link, counts of
// samples, malformed lines and gaps in t, and its measured sample rate. A UI shows each as a
// distinct condition (htop-style: NaN means "not known yet", drawn as a dash).
//
// Units: t in s on the source's own clock (the `t` field of the samples); ages and durations in
// s of wall time (steady clock); rate in Hz.
#pragma once

#include <string>
#include <string_view>

#include "accelcal/base/capture.h"
#include "accelcal/base/sample_format.h"

namespace accelcal {

enum class LinkState {
  kConnecting,  // not yet delivering: opening, connecting, or waiting to retry after a failure
  kUp,          // open, and samples arrived within the last dead_after_s
  kDead,        // no sample for dead_after_s (a silent or cut link; reopening goes on)
  kEnded,       // the source is finished (end of a file or of standard input); nothing more comes
};

// "connecting", "up", "dead", "ended".
std::string_view LinkStateToString(LinkState state);

// A jump in t larger than gap_factor times the median sample interval.
struct TimeGap {
  double t_before_s = kNaN;  // t of the last sample before the gap
  double t_after_s = kNaN;   // t of the first sample after it
  double missing_s = kNaN;   // (t_after - t_before) minus one median interval: time with no data
};

// What kind of thing a notice tells (SourceStatus::last_notice_kind), so that a front end can say
// it in the bench's words without reading the source's own sentence.
enum class SourceNoticeKind {
  kOther,
  kRestarted,       // the device rebooted (its clock went back): the samples go on after a gap
  kRateRequest,     // the rate request was refused or unanswered: asked another way
  kCoarserReadings, // the preferred message did not come: a coarser one is read instead
  kDeviceSilent,    // the device stopped answering (no heartbeat): gone, rebooting or unplugged
  kSamplesLost,     // samples the device made never arrived (a buffer overrun)
};

struct SourceStatus {
  LinkState link = LinkState::kConnecting;
  // Why the link is not up, when known: "read /dev/ttyUSB0: Input/output error",
  // "connect 10.0.0.2:5000: Connection refused", "no sample for 2.0 s". Empty when up.
  std::string link_error;
  long samples_total = 0;
  long malformed_lines = 0;
  // The latest malformed line's complaint, "line 1042, column 7: field 'ay': 'x' is not a
  // number" (non-printable bytes shown as '?'); empty when none so far.
  std::string last_malformed;
  long gaps = 0;
  TimeGap last_gap;             // the latest gap (NaN fields when none so far)
  long reconnects = 0;          // times the link came back after being lost
  double rate_hz = kNaN;        // median of recent sample intervals, inverted; NaN until known
  double last_t_s = kNaN;       // t of the latest sample
  double since_last_sample_s = kNaN;  // wall time since the latest sample (as of the last Read)
  // What a reading's counts are (a MAVLink stream in m/s^2 is taken as counts of 0.001 m/s^2;
  // the text links: counts unless their format says otherwise), once the source knows.
  ReadingUnit unit;
  // The step between two readings the source can deliver, counts (SCALED_IMU's 1 mG is 9.80665
  // counts of 0.001 m/s^2; an ADC's 1 count); NaN: unknown or finer than anything that matters
  // (a float). A noise floor near or below step / sqrt(12) is the rounding, not the sensor.
  double resolution_counts = kNaN;
  // Samples the sender numbered but that never arrived: MAVLink sequence gaps, IIO timestamps
  // that jump (buffer overruns).
  long lost_frames = 0;
  // The latest event that is neither a sample nor an error: "system 1 rebooted ...", "the
  // vehicle refused SET_MESSAGE_INTERVAL ...". Empty when none.
  std::string last_notice;
  SourceNoticeKind last_notice_kind = SourceNoticeKind::kOther;

  // One line for a status bar: "up, 100.0 Hz, 1234 samples, 0 malformed, 0 gaps".
  std::string BriefReport() const;
  // What the resolution means for a noise figure, for the noise floor to say: "the readings come
  // in steps of 9.81 counts (1 mG): a noise below 2.83 counts (step / sqrt 12) is the rounding,
  // not the sensor; a quantised stream is not a quiet sensor". Empty when the step is unknown.
  std::string ResolutionNote() const;
};

// What happened during one SampleSource::Read call, so that each event can be shown once.
struct ReadResult {
  long samples = 0;          // samples appended to the caller's vector
  long malformed = 0;        // malformed lines seen (status().last_malformed has the latest)
  long gaps = 0;             // gaps in t seen (status().last_gap has the latest)
  bool link_lost = false;    // the link failed (read error, hang-up, disconnect)
  bool went_dead = false;    // the link became dead (no sample for dead_after_s)
  bool reconnected = false;  // the link came back after being lost or dead
  bool ended = false;        // the source finished in this call (it stays ended)
  bool notice = false;       // status().last_notice changed in this call
};

}  // namespace accelcal
