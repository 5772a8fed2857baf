#include "accelcal/base/utc_time.h"

#include <chrono>
#include <ctime>

#include <fmt/core.h>

namespace accelcal {
namespace {

std::tm UtcNow(long* millis) {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  *millis = static_cast<long>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                  now.time_since_epoch()).count() % 1000);
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  return tm;
}

}  // namespace

std::string UtcNowIso8601() {
  long ms = 0;
  const std::tm t = UtcNow(&ms);
  return fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}.{:03}Z", t.tm_year + 1900, t.tm_mon + 1,
                     t.tm_mday, t.tm_hour, t.tm_min, t.tm_sec, ms);
}

std::string UtcNowCompact() {
  long ms = 0;
  const std::tm t = UtcNow(&ms);
  return fmt::format("{:04}{:02}{:02}T{:02}{:02}{:02}Z", t.tm_year + 1900, t.tm_mon + 1, t.tm_mday,
                     t.tm_hour, t.tm_min, t.tm_sec);
}

std::string ShortUtc(const std::string& iso) {
  std::string d = iso.substr(0, 19);
  if (d.size() > 10 && d[10] == 'T') d[10] = ' ';
  return d;
}

}  // namespace accelcal
