// A record step (noise, drift: minutes to hours of a static sensor) streamed to the session
// journal in chunks, resumable, with the live figures its view shows.
//
// Clock: the record's own (session_journal.h). The first run keeps the source's t; a resumed
// run shifts its samples so that the first one comes `gap` after the last sample stored, the
// gap measured on the computer's clock (the only clock the two runs share: a source's t may
// restart, as the simulator's does) from the last committed chunk to the first new sample.
// The gap covers the chunk that was being filled when the run died and the time down.
//
// Duration: duration_s is the span of the record's clock, gaps included (a 12-hour record ends
// 12 hours after it began, however often it was interrupted; the gaps are what it lacks). The
// record is complete at the first sample at or beyond t_first + duration_s.
//
// A record is never refused: its drift is what it is for. A movement (a sample farther than
// bump_sigmas noise-floor sigmas from the running mean on some axis) is counted and shown, and
// the record goes on.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/analysis/record_analysis.h"
#include "accelcal/base/capture.h"
#include "accelcal/base/duration_text.h"
#include "accelcal/session/session_journal.h"
#include "accelcal/app/wizard/wizard_view.h"

namespace accelcal {

struct RecordStepWriterOptions {
  double duration_s = 60.0;  // span to record, s; > 0
  double chunk_s = 10.0;     // record time per committed chunk, s; > 0
  // Noise floor per axis (counts, finite, >= 0): the scale of the movement check.
  Eigen::Vector3d noise_std_counts = Eigen::Vector3d::Ones();
  // A reading this many noise sigmas (and at least min_bump_counts) from the running mean is a
  // movement. 6 sigma: one false alarm in ~10^9 Gaussian samples, i.e. about none in a 12-hour
  // record at 100 Hz (4.3e6 samples x 3 axes); the same factor as the capture screening's spike.
  double bump_sigmas = 6.0;
  double min_bump_counts = 2.0;  // floor for a quantized, nearly noise-free signal
  double running_mean_s = 1.0;   // time constant of the running mean, s
  int drift_points = 200;        // bins of the drift plot over the whole duration
  double reference_s = 60.0;     // the drift is relative to the mean of the first this-long, s
  // The computer's clock, s since the Unix epoch (replaceable in tests).
  std::function<double()> wall_now_s;

  // Empty when valid, else the problem.
  std::string Validate() const;
};

class RecordStepWriter {
 public:
  // Borrows `journal` (outlives the stream). Reads what the journal holds for `step_id`: an
  // interrupted record is rebuilt (figures included) and resumed. Throws accelcal::Error for
  // invalid options.
  RecordStepWriter(SessionJournal& journal, std::string step_id, RecordStepWriterOptions options);

  // Appends samples (the source's clock). Each chunk is committed as soon as it is complete;
  // the last one when the duration is covered (later samples are ignored).
  void Feed(const std::vector<Sample>& samples);

  // Commits the chunk being filled now (the operator leaves the record); nothing when empty.
  void Flush() { Commit(); }

  bool complete() const { return complete_; }
  // True when the journal held part of this record at construction.
  bool resuming() const { return resumed_from_.num_chunks > 0; }
  // What the journal held at construction.
  const RecordSummary& resumed_from() const { return resumed_from_; }
  // What is committed now.
  const RecordSummary& committed() const { return committed_; }
  // The live figures (view-model).
  RecordView View() const;
  // "45 min recorded over 46 min, 1 gap (12 s), no movement": the step's outcome.
  std::string Outcome() const;
  // The noise and drift analysis of everything recorded so far, in counts (Allan deviation,
  // read-offs, drift of 1-minute means).
  RecordAnalysis Analysis() const;

 private:
  struct Bin {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    long n = 0;
  };

  void Accept(const Sample& s);
  void Accumulate(const Sample& s);
  void CheckMovement(const Sample& s);
  void Commit();
  double DriftBinS() const;

  SessionJournal& journal_;  // borrowed
  std::string step_id_;
  RecordStepWriterOptions options_;
  RecordSummary resumed_from_;
  RecordSummary committed_;
  bool complete_ = false;

  bool offset_known_ = false;  // this run's shift from the source's t to the record's
  double offset_s_ = 0.0;
  std::optional<RecordGap> pending_gap_;  // to commit with the next chunk
  std::vector<Sample> pending_;           // the chunk being filled (record clock)
  double t_first_s_ = kNaN;               // the record's first sample

  Eigen::Vector3d reference_sum_ = Eigen::Vector3d::Zero();
  long reference_n_ = 0;
  std::vector<Bin> bins_;
  Eigen::Vector3d running_mean_ = Eigen::Vector3d::Constant(kNaN);
  double last_t_s_ = kNaN;
  long bumps_ = 0;
  double last_bump_t_s_ = -1e300;  // latest flagged sample, s
  double bump_start_t_s_ = 0.0;    // first flagged sample of the latest movement, s
  std::string last_bump_;

  // The live analysis. Mutable: asking for a curve brings the accumulators' sums up to date
  // (record_analysis.h), which the const View() does, at most once per new ~1 % of samples.
  mutable RecordAnalyzer analyzer_;
  mutable long allan_at_samples_ = -1;
  mutable std::array<std::vector<AllanCurvePoint>, 3> allan_;
};

}  // namespace accelcal
