#include "accelcal/base/sample_time_check.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "accelcal/base/text_scan.h"

namespace accelcal::detail {
void SampleTimeCheck::AddWithChecks(const Sample& sample, std::string_view line,
                                    long line_number, size_t t_offset, std::vector<Sample>* out,
                                    std::vector<InputError>* errors) {
  Held h{sample, line_number, 0};
  if (has_previous_ && sample.t_s < last_seen_t_s_) {
    errors->push_back(OrderError(line_number, ColumnAt(line, t_offset), sample.t_s,
                                 last_seen_line_, last_seen_t_s_));
    return;
  }
  const bool tie = has_previous_ && sample.t_s == last_seen_t_s_;
  if (tie) h.column = ColumnAt(line, t_offset);
  switch (mode_) {
    case Mode::kStrict:
      if (!tie || !repair_ties_) {
        StrictAdd(h, out, errors);
        return;
      }
      mode_ = Mode::kSuspect;
      held_.assign(1, h);
      held_ties_ = 1;
      last_seen_line_ = line_number;
      return;
    case Mode::kSuspect:
      held_.push_back(h);
      held_ties_ += tie ? 1 : 0;
      last_seen_t_s_ = sample.t_s;
      last_seen_line_ = line_number;
      if (held_ties_ >= kMinTies) {
        ResolveSuspect(true, out, errors);
      } else if (static_cast<int>(held_.size()) >= kEvidenceSamples) {
        ResolveSuspect(false, out, errors);
      }
      return;
    case Mode::kRepair:
      last_seen_t_s_ = sample.t_s;
      last_seen_line_ = line_number;
      RepairAdd(h, out, errors);
      return;
  }
}

void SampleTimeCheck::Finish(std::vector<Sample>* out, std::vector<InputError>* errors) {
  if (mode_ == Mode::kSuspect) ResolveSuspect(held_ties_ >= kMinTies, out, errors);
  if (mode_ == Mode::kRepair) CloseGroup(kNaN, out, errors);
}

void SampleTimeCheck::StrictAdd(const Held& h, std::vector<Sample>* out,
                                std::vector<InputError>* errors) {
  if (has_previous_ && !(h.sample.t_s > previous_t_s_)) {
    errors->push_back(TieError(h));
    return;
  }
  Accept(h.sample, h.line, out);
}

// The samples held since a first tie: rounded stamps (repair them, and every later tie), or
// repeated lines (each tie an error).
void SampleTimeCheck::ResolveSuspect(bool rounded, std::vector<Sample>* out,
                                     std::vector<InputError>* errors) {
  std::vector<Held> held = std::move(held_);
  held_.clear();
  held_ties_ = 0;
  if (!rounded) {
    mode_ = Mode::kStrict;
    for (const Held& h : held) StrictAdd(h, out, errors);
    last_seen_t_s_ = previous_t_s_;
    last_seen_line_ = previous_line_;
    return;
  }
  mode_ = Mode::kRepair;
  group_stamp_s_ = previous_t_s_;  // the first tie's group: its first sample went out already
  group_rest_.clear();
  for (const Held& h : held) RepairAdd(h, out, errors);
}

void SampleTimeCheck::RepairAdd(const Held& h, std::vector<Sample>* out,
                                std::vector<InputError>* errors) {
  if (h.sample.t_s == group_stamp_s_) {
    group_rest_.push_back(h);
    return;
  }
  CloseGroup(h.sample.t_s, out, errors);
  group_stamp_s_ = h.sample.t_s;
  previous_t_s_ = h.sample.t_s;
  previous_line_ = h.line;
  NoteStamp(h.sample.t_s);
  Deliver(h.sample, out);
}

// Spreads the samples that share the current stamp (after its first) within its step.
void SampleTimeCheck::CloseGroup(double next_stamp_s, std::vector<Sample>* out,
                                 std::vector<InputError>* errors) {
  if (group_rest_.empty()) return;
  const double k = static_cast<double>(group_rest_.size() + 1);
  double dt = TypicalIntervalS();
  if (std::isfinite(next_stamp_s)) {
    const double local = (next_stamp_s - group_stamp_s_) / k;
    dt = std::isfinite(dt) ? std::min(dt, local) : local;
  }
  if (!(dt > 0.0)) {  // nothing to spread them by (one stamp for the whole stream)
    for (const Held& h : group_rest_) errors->push_back(TieError(h));
    group_rest_.clear();
    return;
  }
  for (size_t j = 0; j < group_rest_.size(); ++j) {
    Sample s = group_rest_[j].sample;
    s.t_s = group_stamp_s_ + static_cast<double>(j + 1) * dt;
    Deliver(s, out);
    ++repaired_;
  }
  group_rest_.clear();
}

double SampleTimeCheck::TypicalIntervalS() const {
  if (marks_.size() < 2) return kNaN;
  const StampMark& newest = marks_[(marks_next_ + marks_.size() - 1) % marks_.size()];
  const StampMark& oldest = marks_.size() < kMarks ? marks_.front() : marks_[marks_next_];
  if (newest.index <= oldest.index) return kNaN;
  return (newest.t_s - oldest.t_s) / static_cast<double>(newest.index - oldest.index);
}

InputError SampleTimeCheck::TieError(const Held& h) const {
  return OrderError(h.line, h.column, h.sample.t_s, previous_line_, previous_t_s_);
}

InputError SampleTimeCheck::OrderError(long at, long column, double t_s, long previous,
                                       double previous_t_s) const {
  const std::string words = fmt::format("t = {} s does not increase ({} {} has t = {} s); t must be "
                                        "strictly increasing", FormatNumber(t_s),
                                        topic_.empty() ? "line" : "message", previous,
                                        FormatNumber(previous_t_s));
  if (topic_.empty()) return InputError(source_name_, at, column, words);
  return InputError(source_name_, 0, 0, fmt::format("{} message {}: {}", topic_, at, words));
}

double SampleTimeCheck::MedianIntervalS() const {
  if (first_intervals_s_.empty()) return kNaN;
  std::vector<double> v = first_intervals_s_;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace accelcal::detail
