#include "accelcal/acquire/source/wall_clock.h"

#include <chrono>
#include <thread>

namespace accelcal::source_detail {

double WallNowS() {
  using Clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

void SleepS(double duration_s) {
  if (duration_s <= 0.0) return;
  std::this_thread::sleep_for(std::chrono::duration<double>(duration_s));
}

}  // namespace accelcal::source_detail
