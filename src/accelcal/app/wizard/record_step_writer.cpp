#include "accelcal/app/wizard/record_step_writer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

double SystemNowS() {
  using namespace std::chrono;
  return duration<double>(system_clock::now().time_since_epoch()).count();
}

// The smallest gap a resume records: the two runs' samples must not share a t, s.
constexpr double kMinGapS = 1e-3;
constexpr const char* kResumeReason = "resumed after interruption";
constexpr const char* kAxisNames = "xyz";

// The record analysis as the wizard runs it: a resumed record may have been down for days.
RecordAnalysisOptions LiveAnalysisOptions() {
  RecordAnalysisOptions o;
  o.max_gap_s = 60 * 86400.0;
  return o;
}

}  // namespace

std::string RecordStepWriterOptions::Validate() const {
  if (!(duration_s > 0.0) || !std::isfinite(duration_s)) return "duration_s must be positive";
  if (!(chunk_s > 0.0) || !std::isfinite(chunk_s)) return "chunk_s must be positive";
  if (!noise_std_counts.allFinite() || (noise_std_counts.array() < 0.0).any())
    return "the noise floor must be finite and >= 0";
  if (!(bump_sigmas > 0.0) || !(min_bump_counts >= 0.0)) return "the movement limits must be positive";
  if (!(running_mean_s > 0.0)) return "running_mean_s must be positive";
  if (drift_points < 1) return "drift_points must be at least 1";
  if (!(reference_s > 0.0)) return "reference_s must be positive";
  return "";
}

RecordStepWriter::RecordStepWriter(SessionJournal& journal, std::string step_id, RecordStepWriterOptions options)
    : journal_(journal),
      step_id_(std::move(step_id)),
      options_(std::move(options)),
      analyzer_(LiveAnalysisOptions(), "counts") {
  if (std::string why = options_.Validate(); !why.empty()) throw Error("record: " + why);
  if (!options_.wall_now_s) options_.wall_now_s = SystemNowS;
  resumed_from_ = journal_.RecordSummaryOf(step_id_);
  committed_ = resumed_from_;
  // Rebuild the figures from what is stored, one chunk at a time.
  journal_.VisitRecordChunks(step_id_, [&](const RecordChunk& chunk) {
    for (const Sample& s : chunk.samples) Accumulate(s);
  });
  if (resuming()) complete_ = committed_.span_s() >= options_.duration_s;
}

void RecordStepWriter::Feed(const std::vector<Sample>& samples) {
  for (const Sample& raw : samples) {
    if (complete_) return;
    // An unreadable line (NaN or infinite) is not a sample of the record: the record's analysis
    // refuses NaN readings, and a silent link's NaN lines must leave the record as it was.
    if (!std::isfinite(raw.t_s) || !raw.raw_counts.allFinite()) continue;
    if (!offset_known_) {
      offset_known_ = true;
      if (resuming()) {
        const double wall_gap_s = options_.wall_now_s() - resumed_from_.last_wall_end_s;
        const double gap_s = std::max(kMinGapS, std::isfinite(wall_gap_s) ? wall_gap_s : 0.0);
        offset_s_ = resumed_from_.t_last_s + gap_s - raw.t_s;
        pending_gap_ = RecordGap{resumed_from_.t_last_s, raw.t_s + offset_s_, kResumeReason};
      }
    }
    Sample s = raw;
    s.t_s = raw.t_s + offset_s_;
    // A t that does not move on (a source that went back) cannot be stored: skip it.
    const double last_t_s = pending_.empty() ? committed_.t_last_s : pending_.back().t_s;
    if (!std::isnan(last_t_s) && !(s.t_s > last_t_s)) continue;
    Accept(s);
  }
}

void RecordStepWriter::Accept(const Sample& s) {
  if (!pending_.empty() && s.t_s - pending_.front().t_s >= options_.chunk_s) Commit();
  pending_.push_back(s);
  CheckMovement(s);
  Accumulate(s);
  if (s.t_s - t_first_s_ >= options_.duration_s) {
    Commit();
    complete_ = true;
  }
}

void RecordStepWriter::Commit() {
  if (pending_.empty()) return;
  RecordChunk chunk;
  chunk.index = committed_.num_chunks;
  chunk.samples = std::move(pending_);
  chunk.wall_end_s = options_.wall_now_s();
  chunk.gap_before = pending_gap_;
  journal_.AppendRecordChunk(step_id_, chunk);
  committed_ = AddToSummary(committed_, chunk);
  pending_gap_.reset();
  pending_.clear();
}

double RecordStepWriter::DriftBinS() const {
  return options_.duration_s / static_cast<double>(options_.drift_points);
}

// The figures of one recorded sample (stored or new, in record order). The per-axis Allan
// accumulators of RecordView::allan take the sample here too; a sample that follows a gap
// (t - previous t well beyond one interval) is where they take the missing count.
void RecordStepWriter::Accumulate(const Sample& s) {
  if (std::isnan(t_first_s_)) t_first_s_ = s.t_s;
  if (!s.raw_counts.allFinite()) return;
  const double since_s = s.t_s - t_first_s_;
  if (since_s < options_.reference_s) {
    reference_sum_ += s.raw_counts;
    ++reference_n_;
  }
  // The last sample (at the duration) and any beyond it go into the last bin.
  const double last_bin = static_cast<double>(options_.drift_points - 1);
  const size_t bin = static_cast<size_t>(std::clamp(std::floor(since_s / DriftBinS()), 0.0, last_bin));
  if (bin >= bins_.size()) bins_.resize(bin + 1);
  bins_[bin].sum += s.raw_counts;
  bins_[bin].n += 1;
  // Gaps show as steps in t (a resumed record's samples are shifted past its gap).
  analyzer_.Add(s.t_s, s.raw_counts, std::isfinite(s.temp_c) ? s.temp_c : kNaN);
}

// A movement: far from the running mean on some axis. Flagged samples within one running-mean
// time constant of each other are one movement, and they do not move the mean (a knock must
// not drag it along); a level that stays off for longer than that is a new pose: the mean
// starts over from it.
void RecordStepWriter::CheckMovement(const Sample& s) {
  if (!s.raw_counts.allFinite()) return;
  if (!running_mean_.allFinite() || !(s.t_s - last_t_s_ < options_.running_mean_s)) {
    running_mean_ = s.raw_counts;  // the first sample, or after a gap: start over
    last_t_s_ = s.t_s;
    return;
  }
  const Eigen::Vector3d limit =
      (options_.bump_sigmas * options_.noise_std_counts).cwiseMax(options_.min_bump_counts);
  const Eigen::Vector3d off = (s.raw_counts - running_mean_).cwiseAbs();
  Eigen::Index axis = 0;
  const double worst = (off.array() / limit.array()).maxCoeff(&axis);
  if (worst > 1.0) {
    if (s.t_s - last_bump_t_s_ > options_.running_mean_s) {
      ++bumps_;
      bump_start_t_s_ = s.t_s;
      last_bump_ = fmt::format("at {}, {:.0f} counts on {}", FormatClock(s.t_s - t_first_s_),
                               off(axis), kAxisNames[axis]);
    }
    last_bump_t_s_ = s.t_s;
    if (s.t_s - bump_start_t_s_ > options_.running_mean_s) running_mean_ = s.raw_counts;
    last_t_s_ = s.t_s;
    return;
  }
  // Exponential running mean with time constant running_mean_s.
  const double alpha = std::min(1.0, (s.t_s - last_t_s_) / options_.running_mean_s);
  running_mean_ += alpha * (s.raw_counts - running_mean_);
  last_t_s_ = s.t_s;
}

RecordView RecordStepWriter::View() const {
  RecordView v;
  v.duration_s = options_.duration_s;
  const double t_last = !pending_.empty() ? pending_.back().t_s : committed_.t_last_s;
  v.elapsed_s = std::isnan(t_first_s_) || std::isnan(t_last) ? 0.0 : t_last - t_first_s_;
  v.gaps = committed_.num_gaps + (pending_gap_ ? 1 : 0);
  v.gaps_s = committed_.gaps_s + (pending_gap_ ? pending_gap_->duration_s() : 0.0);
  v.recorded_s = v.elapsed_s - v.gaps_s;
  v.samples = committed_.num_samples + static_cast<long>(pending_.size());
  v.chunks = committed_.num_chunks;
  v.bumps = bumps_;
  v.last_bump = last_bump_;
  v.drift_bin_s = DriftBinS();
  if (reference_n_ > 0) {
    const Eigen::Vector3d reference = reference_sum_ / static_cast<double>(reference_n_);
    for (size_t i = 0; i < bins_.size(); ++i) {
      if (bins_[i].n == 0) continue;
      v.drift.push_back({(static_cast<double>(i) + 0.5) * DriftBinS(),
                         bins_[i].sum / static_cast<double>(bins_[i].n) - reference});
    }
  }
  if (allan_at_samples_ < 0 || v.samples - allan_at_samples_ >= std::max(1L, v.samples / 100)) {
    allan_at_samples_ = v.samples;
    const RecordAnalysis a = analyzer_.Result();
    for (size_t axis = 0; axis < 3; ++axis) {
      allan_[axis].clear();
      for (const AllanPoint& p : a.axes[axis].curve.points) allan_[axis].push_back({p.tau_s, p.adev});
    }
  }
  v.allan = allan_;
  return v;
}

RecordAnalysis RecordStepWriter::Analysis() const { return analyzer_.Result(); }

std::string RecordStepWriter::Outcome() const {
  const RecordView v = View();
  return fmt::format("recorded {} over {}, {} gap{} ({}), {} movement{}",
                     FormatLongDuration(v.recorded_s), FormatLongDuration(v.elapsed_s), v.gaps,
                     v.gaps == 1 ? "" : "s", FormatLongDuration(v.gaps_s), v.bumps,
                     v.bumps == 1 ? "" : "s");
}

}  // namespace accelcal
