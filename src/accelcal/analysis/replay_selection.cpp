#include "accelcal/analysis/replay_selection.h"

#include <algorithm>
#include <cstring>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal::analysis {
namespace {

std::uint64_t Bits(double value) {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

double FromBits(std::uint64_t bits) {
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace

bool ReplaySelection::IsCandidate(std::uint64_t bits) const {
  return level_ == 0 || (bits >> (64 - kDigitBits * level_)) == prefix_;
}

void ReplaySelection::Add(double value) {
  const std::uint64_t bits = Bits(value);
  if (!IsCandidate(bits)) return;
  if (histogram_.empty()) histogram_.assign(std::size_t{1} << kDigitBits, 0);
  ++histogram_[(bits >> (64 - kDigitBits * (level_ + 1))) & ((1u << kDigitBits) - 1)];
  ++candidates_;
  CountDistinct(value);
}

void ReplaySelection::CountDistinct(double value) {
  if (distinct_overflow_) return;
  for (std::size_t i = 0; i < num_distinct_; ++i) {
    if (distinct_[i].first == value) {
      ++distinct_[i].second;
      return;
    }
  }
  if (num_distinct_ == kMaxDistinct) {
    distinct_overflow_ = true;
    return;
  }
  distinct_[num_distinct_++] = {value, 1};
}

void ReplaySelection::ResolveFromDistinct(std::uint64_t rank) {
  std::sort(distinct_.begin(), distinct_.begin() + static_cast<long>(num_distinct_));
  std::uint64_t below = 0;
  for (std::size_t i = 0; i < num_distinct_; ++i) {
    below += distinct_[i].second;
    if (rank < below) {
      result_ = distinct_[i].first;
      return;
    }
  }
  throw Error("selection: the values changed between passes");  // fewer than rank + 1
}

bool ReplaySelection::EndPass(std::uint64_t k) {
  if (passes_ == 0) {
    if (k >= candidates_)
      throw Error(fmt::format("selection: index {} of {} values", k, candidates_));
    rank_ = k;
  }
  ++passes_;
  bool done = false;
  if (!distinct_overflow_) {
    ResolveFromDistinct(rank_);
    done = true;
  } else {
    // The bucket of the next digit that holds the rank_-th candidate.
    std::uint64_t below = 0;
    std::uint64_t digit = 0;
    while (digit < histogram_.size() && below + histogram_[digit] <= rank_)
      below += histogram_[digit++];
    if (digit == histogram_.size())  // fewer candidates than at the pass before
      throw Error("selection: the values changed between passes");
    rank_ -= below;
    prefix_ = (prefix_ << kDigitBits) | digit;
    ++level_;
    if (level_ * kDigitBits == 64) {
      result_ = FromBits(prefix_);
      done = true;
    }
  }
  std::fill(histogram_.begin(), histogram_.end(), 0);
  candidates_ = 0;
  num_distinct_ = 0;
  distinct_overflow_ = false;
  if (done) histogram_ = {};
  return done;
}

}  // namespace accelcal::analysis
