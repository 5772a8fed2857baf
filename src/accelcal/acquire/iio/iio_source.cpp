#include "accelcal/acquire/iio/iio_source.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "accelcal/acquire/source/wall_clock.h"
#include "accelcal/base/error.h"
#include "accelcal/base/text_scan.h"

namespace accelcal {
namespace {

namespace fs = std::filesystem;
using source_detail::SleepS;
using source_detail::WallNowS;

constexpr double kDefaultPollHz = 100.0;
constexpr size_t kReadBytes = 64 * 1024;
constexpr double kOverrunPeriods = 1.5;  // a timestamp step beyond this many periods: samples lost

int IioPollMs(double until_s) {
  const double left_s = until_s - WallNowS();
  return left_s <= 0.0 ? 0 : static_cast<int>(std::ceil(std::min(left_s, 3600.0) * 1000.0));
}

// Every *_en file of the scan directory but the ones we read is turned off: the record then
// holds exactly what we lay out.
bool EnableOnly(const IioDevice& d, std::string* error) {
  std::vector<std::string> ours;
  for (const IioChannel& c : d.axes) ours.push_back("in_" + c.name + "_en");
  if (d.timestamp) ours.push_back("in_timestamp_en");
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(d.scan_dir, ec)) {
    const std::string file = e.path().filename();
    if (file.size() < 4 || file.compare(file.size() - 3, 3, "_en") != 0 || file.rfind("in_", 0) != 0) continue;
    const bool on = std::find(ours.begin(), ours.end(), file) != ours.end();
    if (!WriteAttribute(e.path(), on ? "1" : "0", error)) return false;
  }
  return true;
}

}  // namespace

IioSource::IioSource(IioSourceSpec spec, const SourceOptions& options)
    : spec_(std::move(spec)),
      device_(FindIioDevice(spec_)),
      tracker_(options.gap_factor, options.dead_after_s, WallNowS()),
      backoff_(options.reconnect_initial_s, options.reconnect_max_s) {
  buffered_ = device_.buffered() && !spec_.poll;
  if (!buffered_)
    for (const IioChannel& c : device_.axes)
      if (c.raw_path.empty())
        throw Error(fmt::format("{}: in_{}_raw is missing, so the channel cannot be polled",
                                device_.Label(), c.name));
  tracker_.SetUnit(ReadingUnit{}, 1.0);
}

IioSource::~IioSource() {
  if (fd_ >= 0) ::close(fd_);
  if (open_ && buffered_) StopBuffer();
}

std::string IioSource::Named(const std::string& what) const {
  return fmt::format("{} {}: {}", Describe(), device_.Label(), what);
}

ReadResult IioSource::Read(double timeout_s, std::vector<Sample>* out) {
  ReadResult result;
  const double deadline_s = WallNowS() + std::max(0.0, timeout_s);
  for (;;) {
    if (!open_ && !TryOpen(deadline_s, &result)) {
      if (WallNowS() >= deadline_s) break;
      continue;
    }
    if (buffered_) {
      pollfd p{fd_, POLLIN, 0};
      const int rc = poll(&p, 1, IioPollMs(deadline_s));
      if (rc > 0) ReadRecords(&result);
      else if (rc < 0 && errno != EINTR) Lost(std::string("poll: ") + std::strerror(errno), &result);
    } else {
      const double now_s = WallNowS();
      if (now_s < next_poll_wall_s_) SleepS(std::min(deadline_s, next_poll_wall_s_) - now_s);
      PollDue(WallNowS(), &result);
    }
    // Deliver in bursts of at least a few ms (as the paced sources do), or at the deadline.
    if (!ready_.empty() || WallNowS() >= deadline_s) break;
  }
  if (!ready_.empty()) {
    out->insert(out->end(), ready_.begin(), ready_.end());
    tracker_.OnSamples(ready_.data(), static_cast<long>(ready_.size()), WallNowS(), &result);
    ready_.clear();
  }
  tracker_.SetLostFrames(lost_samples_);
  tracker_.Tick(WallNowS(), &result, !last_read_error_.empty() ? last_read_error_ : last_loss_);
  return result;
}

bool IioSource::TryOpen(double deadline_s, ReadResult* result) {
  const double now_s = WallNowS();
  if (!backoff_.Due(now_s, deadline_s)) return false;
  std::string error;
  try {
    device_ = FindIioDevice(spec_);  // it may have come back under another number
  } catch (const Error& e) {
    error = e.what();
  }
  if (error.empty() && buffered_ && !StartBuffer(&error)) error = Named(error);
  if (error.empty() && buffered_) {
    fd_ = ::open(device_.dev_file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd_ < 0) error = Named(fmt::format("open {}: {}", device_.dev_file, std::strerror(errno)));
  }
  if (!error.empty()) {
    // After a loss, the loss says more than the retry's own failure.
    tracker_.OnOpenFailed(lost_why_.empty() ? error : lost_why_ + "; not back yet");
    backoff_.Failed(WallNowS());
    return false;
  }
  if (!buffered_) {
    rate_hz_ = !std::isnan(spec_.rate_hz) ? spec_.rate_hz : kDefaultPollHz;
    rate_note_ = fmt::format("polling in_*_raw at {:g} Hz", rate_hz_);
    t0_wall_s_ = WallNowS();
    next_poll_wall_s_ = t0_wall_s_;
  }
  open_ = true;
  lost_why_.clear();
  pending_.clear();
  backoff_.Succeeded();
  tracker_.OnLinkUp(WallNowS(), result);
  return true;
}

bool IioSource::StartBuffer(std::string* error) {
  std::string ignored;
  WriteAttribute(device_.buffer_dir + "/enable", "0", &ignored);  // changes need it off
  if (!EnableOnly(device_, error)) return false;
  record_bytes_ = LayOutRecord(&device_);
  if (!device_.sampling_frequency_path.empty()) {
    if (!std::isnan(spec_.rate_hz) &&
        !WriteAttribute(device_.sampling_frequency_path, fmt::format("{:g}", spec_.rate_hz), error))
      return false;
    const std::optional<std::string> back = ReadAttribute(device_.sampling_frequency_path, error);
    double hz = kNaN;
    if (back && detail::ParseDouble(detail::TrimBlanks(*back), &hz)) rate_hz_ = hz;
    rate_note_ = std::isnan(spec_.rate_hz)
                     ? fmt::format("sampling_frequency {:g} Hz", rate_hz_)
                     : fmt::format("sampling_frequency asked {:g} Hz, read back {:g} Hz{}", spec_.rate_hz,
                                   rate_hz_, rate_hz_ == spec_.rate_hz ? "" : " (the device's nearest)");
  } else {
    rate_note_ = "no sampling_frequency attribute (the trigger sets the rate)";
  }
  return WriteAttribute(device_.buffer_dir + "/enable", "1", error);
}

void IioSource::StopBuffer() {
  std::string ignored;
  WriteAttribute(device_.buffer_dir + "/enable", "0", &ignored);
}

void IioSource::Lost(const std::string& why, ReadResult* result) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  open_ = false;
  pending_.clear();
  std::error_code ec;
  const bool gone = !fs::exists(device_.dir, ec);
  lost_why_ = Named(gone ? fmt::format("the device went away ({} is gone)", device_.dir) : why);
  last_loss_ = lost_why_;
  tracker_.OnLinkLost(lost_why_, result);
  backoff_.Failed(WallNowS());
}

void IioSource::ReadRecords(ReadResult* result) {
  std::vector<std::uint8_t> chunk(kReadBytes);
  for (;;) {
    const ssize_t n = ::read(fd_, chunk.data(), chunk.size());
    if (n > 0) {
      pending_.insert(pending_.end(), chunk.begin(), chunk.begin() + n);
      continue;
    }
    const int err = errno;
    DecodeRecords(result);  // what came before the end is data
    if (n == 0) Lost(fmt::format("{} ended: the device stopped delivering", device_.dev_file), result);
    else if (err != EAGAIN && err != EWOULDBLOCK && err != EINTR)
      Lost(fmt::format("read {}: {}", device_.dev_file, std::strerror(err)), result);
    return;
  }
}

void IioSource::DecodeRecords(ReadResult* result) {
  const size_t whole = pending_.size() / static_cast<size_t>(record_bytes_) * static_cast<size_t>(record_bytes_);
  const double period_s = 1.0 / rate_hz_;
  for (size_t at = 0; at < whole; at += static_cast<size_t>(record_bytes_)) {
    const std::uint8_t* record = pending_.data() + at;
    Sample s;
    for (int j = 0; j < 3; ++j) {
      const IioScanElement& e = *device_.axes[static_cast<size_t>(j)].scan;
      s.raw_counts(j) = static_cast<double>(e.type.Decode(record + e.offset));
    }
    if (device_.timestamp) {
      const std::int64_t ns = device_.timestamp->type.Decode(record + device_.timestamp->offset);
      if (!first_timestamp_ns_) first_timestamp_ns_ = ns;
      s.t_s = static_cast<double>(ns - *first_timestamp_ns_) * 1e-9;
      const double dt_s = ready_.empty() ? s.t_s - tracker_.status().last_t_s : s.t_s - ready_.back().t_s;
      if (std::isfinite(period_s) && std::isfinite(dt_s) && dt_s > kOverrunPeriods * period_s) {
        const long lost = std::lround(dt_s / period_s) - 1;
        lost_samples_ += lost;
        ++overruns_;
        tracker_.OnNotice(Named(fmt::format("{} sample{} lost between t = {:.4f} s and {:.4f} s (buffer "
                                            "overrun: the records were not read fast enough, or the "
                                            "device skipped them)",
                                            lost, lost == 1 ? "" : "s", s.t_s - dt_s, s.t_s)),
                          result, SourceNoticeKind::kSamplesLost);
      }
    } else {
      s.t_s = std::isfinite(period_s) ? static_cast<double>(records_) * period_s : WallNowS() - t0_wall_s_;
    }
    ++records_;
    last_loss_.clear();
    ready_.push_back(s);
  }
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(whole));
}

void IioSource::PollDue(double now_s, ReadResult* result) {
  if (now_s < next_poll_wall_s_) return;
  next_poll_wall_s_ = std::max(next_poll_wall_s_ + 1.0 / rate_hz_, now_s - 1.0 / rate_hz_);
  Sample s;
  s.t_s = now_s - t0_wall_s_;
  for (int j = 0; j < 3; ++j) {
    const IioChannel& c = device_.axes[static_cast<size_t>(j)];
    std::string error;
    const std::optional<std::string> text = ReadAttribute(c.raw_path, &error);
    double v = kNaN;
    if (!text || !detail::ParseDouble(detail::TrimBlanks(*text), &v)) {
      std::error_code ec;
      if (!fs::exists(device_.dir, ec)) {
        Lost("", result);
        return;
      }
      last_read_error_ = Named(text ? fmt::format("in_{}_raw holds '{}', not a number", c.name, *text) : error);
      tracker_.OnMalformed(1, last_read_error_, result);
      return;
    }
    s.raw_counts(j) = v;
  }
  last_read_error_.clear();
  last_loss_.clear();
  ready_.push_back(s);
}

std::string IioSource::DescribeReading() const {
  std::string text = fmt::format("{}: {}", device_.Label(), buffered_ ? "buffered" : "polled");
  text += fmt::format(" in_{}, in_{}, in_{} as raw counts", device_.axes[0].name, device_.axes[1].name,
                      device_.axes[2].name);
  const IioChannel& x = device_.axes[0];
  text += std::isnan(x.scale) ? " (no scale attribute)"
                              : fmt::format(" ({} {:g} and {} stated, not applied)", x.scale_file, x.scale,
                                            std::isnan(x.offset_counts) ? "no offset" : fmt::format("{} {:g}", x.offset_file, x.offset_counts));
  if (buffered_) {
    text += fmt::format("; records of {} bytes from {} ({}{})", record_bytes_, device_.dev_file,
                        x.scan ? x.scan->type.Describe() : "?",
                        device_.timestamp ? ", timestamp channel" : ", no timestamp channel: lost samples cannot be seen");
    text += device_.has_trigger_file ? (device_.trigger.empty() ? "; trigger: none set" : "; trigger: " + device_.trigger) : "";
  }
  if (!rate_note_.empty()) text += "; " + rate_note_;
  if (!buffered_ && !std::isnan(status().rate_hz)) text += fmt::format(", {:.1f} Hz reached", status().rate_hz);
  if (overruns_ > 0) text += fmt::format("; {} overrun{}, {} samples lost", overruns_, overruns_ == 1 ? "" : "s", lost_samples_);
  return text;
}

std::unique_ptr<SampleSource> OpenIioSource(const IioSourceSpec& spec, const SourceOptions& options) {
  return std::make_unique<IioSource>(spec, options);
}

}  // namespace accelcal
