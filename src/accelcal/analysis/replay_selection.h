// The k-th smallest of a sequence of positive finite doubles that can be read again, exactly and
// in bounded memory: the median interval of a record too long to hold (noise_analysis.h).
//
// Each pass over the values narrows the candidates by 16 more bits of their IEEE 754 pattern
// (for positive doubles the order of the patterns as unsigned integers is the order of the
// values): a histogram of the next 16 bits of the candidates says in which bucket the k-th
// lies (a radix selection; four passes at most, 512 KiB of counts). A pass also counts the
// distinct candidate values while there are at most kMaxDistinct of them: a record's intervals
// usually take a handful of values, and then one pass gives the answer.
//
// The result is the element std::nth_element puts at index k of the sorted sequence.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace accelcal::analysis {

class ReplaySelection {
 public:
  // Call Add with every value of the sequence (the same values, in any order, at every pass),
  // then EndPass; repeat until EndPass returns true. Values must be positive and finite.
  void Add(double value);
  // k: the index in the sorted sequence (0 .. count - 1), the same at every pass. True when
  // Result() is known; throws accelcal::Error when k is not below the count of values, or when
  // a later pass saw fewer of the candidates than the one before.
  bool EndPass(std::uint64_t k);
  double Result() const { return result_; }
  int passes() const { return passes_; }

 private:
  static constexpr int kDigitBits = 16;
  static constexpr std::size_t kMaxDistinct = 64;

  bool IsCandidate(std::uint64_t bits) const;
  void CountDistinct(double value);
  void ResolveFromDistinct(std::uint64_t rank);

  int level_ = 0;              // digits of 16 bits known
  std::uint64_t prefix_ = 0;   // their value (the top 16 * level_ bits of the answer)
  std::uint64_t rank_ = 0;     // the answer's index among the candidates
  std::uint64_t candidates_ = 0;  // counted in this pass
  std::vector<std::uint64_t> histogram_;  // by the next digit, this pass
  std::array<std::pair<double, std::uint64_t>, kMaxDistinct> distinct_{};
  std::size_t num_distinct_ = 0;
  bool distinct_overflow_ = false;
  double result_ = 0.0;
  int passes_ = 0;
};

}  // namespace accelcal::analysis
