// Helpers for the sample-source tests: reading until a condition holds (with a generous
// deadline, never a tight timing assumption), writing to a descriptor from a thread, and lines
// of the protocol.
#pragma once

#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "accelcal/acquire/source/sample_source.h"

namespace accelcal::testing {

// Every event of several Read calls, summed.
inline void Accumulate(const ReadResult& r, ReadResult* total) {
  total->samples += r.samples;
  total->malformed += r.malformed;
  total->gaps += r.gaps;
  total->link_lost |= r.link_lost;
  total->went_dead |= r.went_dead;
  total->reconnected |= r.reconnected;
  total->ended |= r.ended;
}

// Reads until `done(status)` holds or timeout_s passes (wall clock); true when it held.
inline bool ReadUntil(SampleSource& source, std::vector<Sample>* samples,
                      const std::function<bool(const SourceStatus&)>& done,
                      double timeout_s = 30.0, ReadResult* events = nullptr) {
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    const ReadResult r = source.Read(0.05, samples);
    if (events != nullptr) Accumulate(r, events);
    if (done(source.status())) return true;
  }
  return done(source.status());
}

// Writes all of `data` to fd (blocking), retrying partial writes; false on an error.
inline bool WriteAll(int fd, const std::string& data) {
  size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

// Protocol lines for samples first..first+count-1 at rate_hz: "t ax ay az\n" with ax = index.
inline std::string SampleLines(long first, long count, double rate_hz = 100.0,
                               double t_offset_s = 0.0) {
  std::string text;
  for (long i = first; i < first + count; ++i)
    text += fmt::format("{} {} 2000 3000\n", t_offset_s + static_cast<double>(i) / rate_hz, i);
  return text;
}

// True when samples' ax run first, first+1, ... without a hole (order and completeness).
inline bool Consecutive(const std::vector<Sample>& samples, long first = 0) {
  for (size_t i = 0; i < samples.size(); ++i)
    if (samples[i].raw_counts.x() != static_cast<double>(first + static_cast<long>(i))) return false;
  return true;
}

}  // namespace accelcal::testing
