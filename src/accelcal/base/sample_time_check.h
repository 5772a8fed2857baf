// The time stamps of a sample stream, checked in order and, when a logger printed them with too
// few digits, repaired. Part of the sample reader (sample_reader.h).
//
// t must increase. A t that goes back is always an error. A t equal to the one before (a tie)
// is one of two things:
//  - a stamp rounded by the logger ("%.2f" at 200 Hz prints 0, 0, 0.01, 0.01, ...): ties are then
//    systematic. From a first tie on, the check holds the samples that follow, up to
//    kEvidenceSamples; when kMinTies ties or more are among them the stamps are taken as rounded
//    (for the rest of the stream) and every group of k samples sharing a stamp T is spread
//    within its step: t_j = T + j dt (j = 0 .. k-1), dt = min((T_next - T) / k, typical
//    interval), T_next the next stamp and the typical interval that of the last 16 stamps
//    (their time span over the samples between them), so that a group just before a gap is not
//    stretched into it. Repaired t are strictly increasing and stay within one step of the
//    printed ones. The first sample of a group keeps its stamp: it is delivered at once, the
//    rest when the next stamp (or the end) arrives.
//  - otherwise (fewer ties) each tie is a repeated line: an error, as a t going back is:
//    "t = 0.01 s does not increase (line 2 has t = 0.01 s); t must be strictly increasing".
// A refused sample is dropped and its error returned; what was accepted is unaffected.
#pragma once

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/error.h"

namespace accelcal::detail {

class SampleTimeCheck {
 public:
  static constexpr int kEvidenceSamples = 64;
  static constexpr int kMinTies = 3;

  // repair_ties false: every tie is an error.
  SampleTimeCheck(std::string source_name, bool repair_ties)
      : source_name_(std::move(source_name)), repair_ties_(repair_ties) {}

  // The samples are a bag's messages on `topic`, not a text's lines: the errors name them
  // "/imu message 7" (no line or column) in the same words.
  void NameMessages(std::string topic) { topic_ = std::move(topic); }

  // `sample` was read from line `line_number` (`line` its text, its t at byte `t_offset`, for
  // messages). Appends the samples now final to *out, in order; a refused sample's error goes
  // to *errors.
  void Add(const Sample& sample, std::string_view line, long line_number, size_t t_offset,
           std::vector<Sample>* out, std::vector<InputError>* errors) {
    // The common case, inline: nothing held, t after the last sample (in kStrict the last seen
    // is the last accepted), which AddWithChecks would accept the same way.
    if (mode_ == Mode::kStrict && has_previous_ && sample.t_s > last_seen_t_s_) {
      Accept(sample, line_number, out);
      return;
    }
    AddWithChecks(sample, line, line_number, t_offset, out, errors);
  }
  // The end of the stream: held samples are judged and delivered.
  void Finish(std::vector<Sample>* out, std::vector<InputError>* errors);

  bool rounded() const { return mode_ == Mode::kRepair; }
  long repaired() const { return repaired_; }
  // Samples delivered so far.
  long delivered() const { return delivered_; }
  // The smallest step between two successive distinct stamps seen, s; NaN before two.
  double stamp_step_s() const { return stamp_step_s_; }
  // The median interval of the first delivered samples, s; NaN before two.
  double MedianIntervalS() const;

 private:
  enum class Mode { kStrict, kSuspect, kRepair };
  struct Held {
    Sample sample;
    long line = 0;
    long column = 0;  // of t, for a tie's message
  };

  void AddWithChecks(const Sample& sample, std::string_view line, long line_number,
                     size_t t_offset, std::vector<Sample>* out, std::vector<InputError>* errors);
  // A sample after the last accepted one, in strict order: now the last accepted and seen.
  void Accept(const Sample& s, long line_number, std::vector<Sample>* out) {
    has_previous_ = true;
    previous_t_s_ = last_seen_t_s_ = s.t_s;
    previous_line_ = last_seen_line_ = line_number;
    NoteStamp(s.t_s);
    Deliver(s, out);
  }
  void Deliver(const Sample& s, std::vector<Sample>* out) {
    out->push_back(s);
    if (first_intervals_s_.size() < kRateIntervals && std::isfinite(last_delivered_t_s_))
      first_intervals_s_.push_back(s.t_s - last_delivered_t_s_);
    last_delivered_t_s_ = s.t_s;
    ++delivered_;
  }
  void StrictAdd(const Held& h, std::vector<Sample>* out, std::vector<InputError>* errors);
  void ResolveSuspect(bool rounded, std::vector<Sample>* out, std::vector<InputError>* errors);
  void RepairAdd(const Held& h, std::vector<Sample>* out, std::vector<InputError>* errors);
  void CloseGroup(double next_stamp_s, std::vector<Sample>* out, std::vector<InputError>* errors);
  double TypicalIntervalS() const;
  InputError TieError(const Held& h) const;
  // "t = T s does not increase (line P has t = PT s); ..." at line (or message) `at`.
  InputError OrderError(long at, long column, double t_s, long previous, double previous_t_s) const;
  void NoteStamp(double t_s) {
    if (std::isfinite(last_stamp_s_) && t_s > last_stamp_s_) {
      const double step = t_s - last_stamp_s_;
      if (!(step >= stamp_step_s_)) stamp_step_s_ = step;
    }
    last_stamp_s_ = t_s;
    const StampMark mark{t_s, delivered_};
    if (marks_.size() < kMarks) {
      marks_.push_back(mark);
    } else {
      marks_[marks_next_] = mark;
      marks_next_ = marks_next_ + 1 == kMarks ? 0 : marks_next_ + 1;
    }
  }
  static constexpr size_t kMarks = 16;             // stamps the typical interval is taken over
  static constexpr size_t kRateIntervals = 1024;   // intervals the reported rate is the median of

  std::string source_name_;
  std::string topic_;  // non-empty: a bag's messages (NameMessages)
  bool repair_ties_;
  Mode mode_ = Mode::kStrict;
  bool has_previous_ = false;
  double previous_t_s_ = 0.0;  // the last accepted sample's t as printed
  long previous_line_ = 0;
  // The last sample not refused (held ones included): what a t going back is judged against.
  double last_seen_t_s_ = 0.0;
  long last_seen_line_ = 0;
  // kSuspect: the samples since the first tie (that one included), and the ties among them.
  std::vector<Held> held_;
  int held_ties_ = 0;
  // kRepair: the current stamp's group; its first sample is delivered, the rest wait here.
  double group_stamp_s_ = 0.0;
  std::vector<Held> group_rest_;
  // The last stamps where a group started, with the count of samples delivered before it.
  struct StampMark {
    double t_s;
    long index;
  };
  std::vector<StampMark> marks_;  // ring of kMarks
  size_t marks_next_ = 0;
  long delivered_ = 0;
  long repaired_ = 0;
  double stamp_step_s_ = kNaN;
  double last_stamp_s_ = kNaN;
  std::vector<double> first_intervals_s_;  // of the first delivered samples (the rate)
  double last_delivered_t_s_ = kNaN;
};

}  // namespace accelcal::detail
