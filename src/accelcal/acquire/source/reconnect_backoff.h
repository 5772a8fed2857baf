// Exponential back-off between attempts to reopen a link: initial_s, doubling on each failure
// up to max_s, back to initial_s once the link is open. Times are wall-clock s.
#pragma once

#include <algorithm>

#include "accelcal/acquire/source/wall_clock.h"

namespace accelcal {

class ReconnectBackoff {
 public:
  ReconnectBackoff(double initial_s, double max_s)
      : initial_s_(initial_s), max_s_(max_s), delay_s_(initial_s) {}

  // An attempt failed (or the link dropped) at now_s: the next one waits the current delay.
  void Failed(double now_s) {
    next_attempt_s_ = now_s + delay_s_;
    delay_s_ = std::min(2.0 * delay_s_, max_s_);
  }
  // The link is open: the next failure waits initial_s again.
  void Succeeded() {
    delay_s_ = initial_s_;
    next_attempt_s_ = 0.0;
  }
  // Wall time before which no attempt should be made, s.
  double next_attempt_s() const { return next_attempt_s_; }
  // True when an attempt may be made now (at now_s); otherwise sleeps until it may or until
  // deadline_s, whichever comes first, and returns false (the caller loops).
  bool Due(double now_s, double deadline_s) const {
    if (now_s >= next_attempt_s_) return true;
    source_detail::SleepS(std::min(deadline_s, next_attempt_s_) - now_s);
    return false;
  }

 private:
  double initial_s_;
  double max_s_;
  double delay_s_;
  double next_attempt_s_ = 0.0;
};

}  // namespace accelcal
